#include "engine/image/signal_handlers.h"

namespace facet {

SignalHandlers::SignalHandlers(std::initializer_list<int> signals, void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  action.sa_flags = SA_RESTART;  // a read or wait it interrupts goes on
  sigemptyset(&action.sa_mask);
  for (int signal : signals) {
    struct sigaction before {};
    sigaction(signal, nullptr, &before);
    if (before.sa_handler == SIG_IGN) continue;  // ignored on purpose (nohup, a background job): it stays so
    sigaction(signal, &action, nullptr);
    before_.emplace_back(signal, before);
  }
}

SignalHandlers::~SignalHandlers() {
  for (const auto& [signal, before] : before_) sigaction(signal, &before, nullptr);
}

}  // namespace facet

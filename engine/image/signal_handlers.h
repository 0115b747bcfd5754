// A handler for some signals while it lives, the handling before restored
// when it ends; a signal ignored before stays ignored: what holds signals back while outputs are renamed
// (image_io.h), passes them on to a program facet runs (child_process.h)
// and ends a watch between passes.
#pragma once

#include <signal.h>

#include <initializer_list>
#include <utility>
#include <vector>

namespace facet {

class SignalHandlers {
 public:
  SignalHandlers(std::initializer_list<int> signals, void (*handler)(int));
  ~SignalHandlers();
  SignalHandlers(const SignalHandlers&) = delete;
  SignalHandlers& operator=(const SignalHandlers&) = delete;

 private:
  std::vector<std::pair<int, struct sigaction>> before_;
};

}  // namespace facet

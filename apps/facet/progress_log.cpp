#include "progress_log.h"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace facet::cli {

ProgressLog::ProgressLog(std::string label, bool quiet)
    : label_(std::move(label)), quiet_(quiet), terminal_(isatty(STDERR_FILENO) != 0) {}

void ProgressLog::operator()(double done) {
  if (quiet_) return;
  if (terminal_) {
    std::fprintf(stderr, "\r%s %3d%%", label_.c_str(), int(done * 100));
    return;
  }
  const int tenths = int(done * 10);
  if (tenths <= tenthsShown_) return;
  tenthsShown_ = tenths;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The rate so far, held for the rest.
  std::fprintf(stderr, "%s %3d%%, %.1f s elapsed, about %.1f s left\n", label_.c_str(), tenths * 10, elapsed,
               elapsed * (1 - done) / done);
}

void ProgressLog::finish() {
  if (!quiet_ && terminal_) std::fprintf(stderr, "\r%*s\r", int(label_.size()) + 5, "");
}

}  // namespace facet::cli

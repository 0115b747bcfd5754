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
  const auto now = std::chrono::steady_clock::now();
  if (done >= 1 || done <= 0 || now - logged_ < kLogInterval) return;
  logged_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // The rate so far, held for the rest.
  std::fprintf(stderr, "%s %3d%%, %.1f s elapsed, about %.1f s left\n", label_.c_str(), int(done * 100), elapsed,
               elapsed * (1 - done) / done);
}

void ProgressLog::finish() {
  if (quiet_) return;
  if (terminal_) {
    std::fprintf(stderr, "\r%*s\r", int(label_.size()) + 5, "");
    return;
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "%s 100%%, %.1f s elapsed\n", label_.c_str(), elapsed);
}

}  // namespace facet::cli

// A render's progress on stderr: one line rewritten in place on a terminal;
// in a log file (a farm's), a line at every tenth with the time left.
#pragma once

#include <chrono>
#include <string>

namespace facet::cli {

class ProgressLog {
 public:
  // `label` names the work in each line, e.g. "frame 12"; `quiet` shows nothing.
  ProgressLog(std::string label, bool quiet);

  // The finished fraction, from the render's progress callback.
  void operator()(double done);
  // Clears the terminal's line.
  void finish();

 private:
  std::string label_;
  bool quiet_;
  bool terminal_;
  int tenthsShown_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace facet::cli

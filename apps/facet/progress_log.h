// A render's progress on stderr: one line rewritten in place on a terminal;
// in a log file (a farm's), a line at most every kLogInterval with the time
// left, and one when the render ends, so that a short render logs one line.
#pragma once

#include <chrono>
#include <string>

namespace facet::cli {

class ProgressLog {
 public:
  static constexpr std::chrono::seconds kLogInterval{10};

  // `label` names the work in each line, e.g. "frame 12"; `quiet` shows nothing.
  ProgressLog(std::string label, bool quiet);

  // The finished fraction, from the render's progress callback.
  void operator()(double done);
  // Clears the terminal's line, or logs the time the render took.
  void finish();

 private:
  std::string label_;
  bool quiet_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point logged_ = start_;
};

}  // namespace facet::cli

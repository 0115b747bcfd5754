// The benchmarks' wall-clock readings (progress, whole runs, CPU builds), in
// milliseconds of a steady clock: only differences of two readings mean
// anything.
#pragma once

#include <chrono>

namespace facet::benchmarks {

inline double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace facet::benchmarks

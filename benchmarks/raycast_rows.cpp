#include "benchmarks/raycast_rows.h"

#include <cmath>
#include <cstdio>

namespace facet::benchmarks::raycast {

std::string fmt(double v, const char* format) {
  if (!std::isfinite(v)) return "—";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string fmtSci(double v) { return fmt(v, "%.1e"); }

}  // namespace facet::benchmarks::raycast

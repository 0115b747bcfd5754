// The Pareto front of points that cost time and carry an error.
#pragma once

#include <cstddef>
#include <vector>

namespace facet::analysis {

struct Cost {
  double milliseconds = 0;
  double error = 0;
};

// Indices of the non-dominated points, fastest first: no other point is both
// faster and at least as accurate. Of equally fast points the most accurate
// is kept.
std::vector<std::size_t> paretoFront(const std::vector<Cost>& points);

}  // namespace facet::analysis

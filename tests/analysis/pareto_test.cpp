// The Pareto front of (time, error) points with a known answer.
#include <gtest/gtest.h>

#include "analysis/pareto.h"

namespace facet::analysis {
namespace {

TEST(ParetoFront, KeepsTheNonDominatedPointsFastestFirst) {
  const std::vector<Cost> points{
      {10, 0.5},   // 0: on the front
      {20, 0.6},   // 1: slower and worse than 0
      {30, 0.1},   // 2: on the front
      {5, 0.9},    // 3: the fastest
      {30, 0.05},  // 4: as fast as 2 and more accurate: replaces it
      {40, 0.05},  // 5: slower than 4, no better
  };
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{3, 0, 4}));
}

TEST(ParetoFront, OnePointIsItsOwnFront) {
  EXPECT_EQ(paretoFront({{1, 1}}), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(paretoFront({}).empty());
}

}  // namespace
}  // namespace facet::analysis

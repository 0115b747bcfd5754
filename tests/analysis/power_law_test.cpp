// Log-log fits on exact power laws: the slope comes back, with no error.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/power_law.h"

namespace facet::analysis {
namespace {

TEST(PowerLaw, ExactPowerLawHasItsSlopeAndZeroStandardError) {
  std::vector<double> x, t;
  for (double v : {1.0, 2.0, 4.0, 8.0, 16.0}) {
    x.push_back(v);
    t.push_back(3.0 * std::pow(v, 1.5));
  }
  const PowerLawFit fit = fitPowerLaw(x, t);
  EXPECT_NEAR(fit.exponent, 1.5, 1e-12);
  EXPECT_NEAR(fit.coefficient, 3.0, 1e-12);
  EXPECT_NEAR(fit.standardError, 0.0, 1e-12);
  EXPECT_EQ(fit.points, 5u);
}

TEST(PowerLaw, FitsFromTheFirstIndexGiven) {
  // A fixed cost flattens the small end; from index 2 on t = x^2 exactly.
  const std::vector<double> x{1, 2, 4, 8}, t{100, 100, 16, 64};
  const PowerLawFit fit = fitPowerLaw(x, t, 2);
  EXPECT_NEAR(fit.exponent, 2.0, 1e-12);
  EXPECT_EQ(fit.points, 2u);
  EXPECT_EQ(fit.standardError, 0.0);  // two points say nothing of it
  EXPECT_EQ(fit.xFirst, 4.0);
  EXPECT_EQ(fit.xLast, 8.0);
}

TEST(PowerLaw, ScatterGivesAStandardError) {
  const std::vector<double> x{1, 2, 4, 8}, t{1, 2.2, 3.8, 8.4};
  EXPECT_GT(fitPowerLaw(x, t).standardError, 0.0);
  EXPECT_THROW(fitPowerLaw(x, {1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace facet::analysis

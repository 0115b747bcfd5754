// Scaling fits: t = a x^b by least squares on log-log axes.
#pragma once

#include <cstddef>
#include <vector>

namespace facet::analysis {

struct PowerLawFit {
  double exponent = 0;           // b
  double coefficient = 0;        // a
  double standardError = 0;      // of b; 0 with fewer than 3 points
  double xFirst = 0, xLast = 0;  // the fitted range
  std::size_t points = 0;
};

// Fits the points from index `first` on (x and t positive).
PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& t, std::size_t first = 0);

}  // namespace facet::analysis

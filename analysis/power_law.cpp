#include "analysis/power_law.h"

#include <cmath>
#include <stdexcept>

namespace facet::analysis {

PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& t, std::size_t first) {
  if (x.size() != t.size() || first >= x.size())
    throw std::invalid_argument("fitPowerLaw: needs as many times as x values, and a point to fit");
  PowerLawFit fit;
  fit.points = x.size() - first;
  fit.xFirst = x[first];
  fit.xLast = x.back();
  double mx = 0, my = 0;
  for (std::size_t i = first; i < x.size(); ++i) {
    mx += std::log(x[i]);
    my += std::log(t[i]);
  }
  const double n = double(fit.points);
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = first; i < x.size(); ++i) {
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
    sxy += (std::log(x[i]) - mx) * (std::log(t[i]) - my);
  }
  fit.exponent = sxx > 0 ? sxy / sxx : 0;
  fit.coefficient = std::exp(my - fit.exponent * mx);
  if (fit.points >= 3 && sxx > 0) {
    double residuals = 0;
    for (std::size_t i = first; i < x.size(); ++i) {
      const double r = std::log(t[i]) - (my + fit.exponent * (std::log(x[i]) - mx));
      residuals += r * r;
    }
    // The slope's standard error of simple linear regression.
    fit.standardError = std::sqrt(residuals / (n - 2) / sxx);
  }
  return fit;
}

}  // namespace facet::analysis

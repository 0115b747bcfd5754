// Quadrature over a polar angle for lobes of any width: Gauss-Legendre on
// panels whose widths grow geometrically from 0, so a peak of width alpha
// at theta = 0 is resolved as well as the broad tail.
#pragma once

#include <cmath>
#include <numbers>

#include "materials/albedo.h"

namespace facet::materials::testing {

// Integral over theta in [0, pi/2] of integrand(theta). A panel edge is
// put at `kink` (if inside), where the integrand may lose smoothness.
template <class Integrand>
double integratePolar(double alpha, const Integrand& integrand, double kink = 0) {
  static const QuadratureRule rule = gaussLegendre01(24);
  double sum = 0;
  double lo = 0;
  double width = alpha / 8;
  const double top = std::numbers::pi / 2;
  while (lo < top) {
    double hi = std::min(top, lo + width);
    if (kink > lo && kink < hi) hi = kink;
    for (size_t i = 0; i < rule.nodes.size(); ++i)
      sum += (hi - lo) * rule.weights[i] * integrand(lo + (hi - lo) * rule.nodes[i]);
    lo = hi;
    width *= 1.5;
  }
  return sum;
}

}  // namespace facet::materials::testing

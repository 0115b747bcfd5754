// The normal distributions and Smith masking, against their defining
// integrals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "materials/models.h"
#include "rules/rules.h"
#include "tests/support/shading_frame.h"
#include "tests/support/quadrature.h"

namespace facet::materials {
namespace {

using facet::testing::kPi;
using testing::integratePolar;
const double kAlphas[] = {0.05, 0.1, 0.25, 0.5, 1.0};

// Integral of D(m)(n.m) over the hemisphere; D depends on theta only.
template <class DFunction>
double projectedArea(double alpha, const DFunction& d) {
  return 2 * kPi * integratePolar(alpha, [&](double theta) {
           return d(std::cos(theta), std::sin(theta) * std::sin(theta)) * std::cos(theta) * std::sin(theta);
         });
}

TEST(Distributions, NormalizedInDouble) {
  // Tolerance 1e-7: the quadrature is good to ~1e-12; what is left is the
  // horizon policy (D = 0 for n.m <= 1e-4 removes at most 1e-8 of the mass).
  double worst = 0;
  for (const ModelName& d : kDistributions) {
    for (double alpha : kAlphas) {
      double area = projectedArea(alpha, [&](double c, double s2) { return rules::f64::microfacet_D(d.id, alpha, c, s2); });
      EXPECT_NEAR(area, 1.0, 1e-7) << d.name << " alpha=" << alpha;
      worst = std::max(worst, std::abs(area - 1));
    }
  }
  RecordProperty("worst_normalization_error_double", std::to_string(worst));
  std::printf("worst |integral D(m)(n.m) - 1|, double: %.3g\n", worst);
}

TEST(Distributions, NormalizedInFloat) {
  // Tolerance 2e-5: the float evaluation of D is good to a few 1e-7
  // relative for these alphas (see the float-vs-double table); the sum is
  // kept in double so only D's own rounding is measured, amplified by the
  // relative error of exp and pow.
  for (const ModelName& d : kDistributions) {
    for (double alpha : kAlphas) {
      double area = projectedArea(alpha, [&](double c, double s2) {
        return double(rules::f32::microfacet_D(d.id, float(alpha), float(c), float(s2)));
      });
      EXPECT_NEAR(area, 1.0, 2e-5) << d.name << " alpha=" << alpha;
    }
  }
}

TEST(Distributions, BlinnPhongExponentMapping) {
  // alpha <-> exponent round trip, and the defining relation e = 2/alpha^2 - 2.
  for (double alpha : kAlphas) {
    double exponent = rules::f64::blinn_phong_exponent(alpha);
    EXPECT_DOUBLE_EQ(exponent, 2 / (alpha * alpha) - 2);
    EXPECT_NEAR(rules::f64::blinn_phong_alpha(exponent), alpha, 1e-15);
  }
  // At alpha = 1 Blinn-Phong is the uniform distribution 1/pi.
  EXPECT_NEAR(rules::f64::microfacet_D(rules::f64::D_BLINN_PHONG, 1.0, 0.3, 0.91), 1 / kPi, 1e-15);
}

// Smith: G1(v) * integral of max(0, v.m) D(m) over m = n.v, the statement
// that the projected area of the visible microfacets equals that of the
// macro surface. The azimuthal integral of max(0, a cos(phi) + b) is done
// in closed form, so only the polar one is numerical.
double visibleProjectedArea(int surface, double alpha, double theta_v) {
  double sv = std::sin(theta_v), cv = std::cos(theta_v);
  return integratePolar(
      alpha,
      [&](double theta) {
        double sm = std::sin(theta), cm = std::cos(theta);
        double a = sv * sm, b = cv * cm;
        double azimuthal;
        if (b >= a) {
          azimuthal = 2 * kPi * b;
        } else {
          double phi0 = std::acos(-b / a);
          azimuthal = 2 * a * std::sin(phi0) + 2 * b * phi0;
        }
        return rules::f64::microfacet_D(surface, alpha, cm, sm * sm) * sm * azimuthal;
      },
      std::numbers::pi / 2 - theta_v);
}

TEST(Distributions, SmithMaskingConservesProjectedArea) {
  // Tolerance 1e-6 relative to n.v: the Beckmann Lambda uses an erfc
  // approximation with absolute error 1.5e-7 (so G1 is within ~1e-7); GGX
  // is exact up to quadrature (~1e-10).
  const double kThetaDegrees[] = {0, 30, 60, 75, 85, 89};
  double worst = 0;
  for (int surface : {rules::f64::D_GGX, rules::f64::D_BECKMANN}) {
    for (double alpha : kAlphas) {
      for (double degrees : kThetaDegrees) {
        double theta = degrees * kPi / 180;
        double lhs = rules::f64::smith_G1(surface, alpha, std::cos(theta)) * visibleProjectedArea(surface, alpha, theta);
        double error = std::abs(lhs - std::cos(theta)) / std::cos(theta);
        EXPECT_LT(error, 1e-6) << modelName(kDistributions, surface) << " alpha=" << alpha << " theta_v=" << degrees;
        worst = std::max(worst, error);
      }
    }
  }
  std::printf("worst relative error of the Smith projected-area identity: %.3g\n", worst);
}

TEST(Distributions, HeightCorrelatedNeverBelowSeparable) {
  // 1 / (1 + L(l) + L(v)) >= 1 / ((1 + L(l))(1 + L(v))) since L >= 0:
  // correlation can only reduce the shadowed fraction.
  for (double alpha : kAlphas) {
    for (double nl : {0.05, 0.3, 0.7, 1.0}) {
      for (double nv : {0.05, 0.5, 1.0}) {
        EXPECT_GE(rules::f64::microfacet_G(rules::f64::G_SMITH_GGX_CORRELATED, alpha, nl, nv, 1, 1),
                  rules::f64::microfacet_G(rules::f64::G_SMITH_GGX, alpha, nl, nv, 1, 1));
        EXPECT_GE(rules::f64::microfacet_G(rules::f64::G_SMITH_BECKMANN_CORRELATED, alpha, nl, nv, 1, 1),
                  rules::f64::microfacet_G(rules::f64::G_SMITH_BECKMANN, alpha, nl, nv, 1, 1));
      }
    }
  }
}

}  // namespace
}  // namespace facet::materials

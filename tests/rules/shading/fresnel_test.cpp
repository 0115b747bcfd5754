// Fresnel terms against the Fresnel equations evaluated independently with
// complex arithmetic (Snell's law and the s/p amplitude coefficients).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "rules/rules.h"

namespace facet::materials {
namespace {

using Complex = std::complex<double>;
const double kDegrees[] = {0, 15, 30, 45, 60, 75, 85, 89.9};

// Unpolarized reflectance from the amplitude coefficients; eta = n + i k
// relative to the incident medium.
double fresnelReference(Complex eta, double cos_i) {
  double sin2_i = 1 - cos_i * cos_i;
  Complex cos_t = std::sqrt(1.0 - sin2_i / (eta * eta));
  Complex rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  Complex rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

double cosDegrees(double degrees) { return std::cos(degrees * std::numbers::pi / 180); }

TEST(Fresnel, DielectricMatchesFresnelEquations) {
  // Tolerance 1e-13 (double) / 1e-6 (float): same equations, rearranged.
  for (double eta : {1.0 / 1.5, 1.33, 1.5, 2.42}) {
    for (double degrees : kDegrees) {
      double c = cosDegrees(degrees);
      double reference = fresnelReference(eta, c);  // |r| = 1 past the critical angle
      EXPECT_NEAR(rules::f64::fresnel_dielectric(eta, c), reference, 1e-13) << "eta=" << eta << " theta=" << degrees;
      EXPECT_NEAR(rules::f32::fresnel_dielectric(float(eta), float(c)), reference, 1e-6)
          << "eta=" << eta << " theta=" << degrees;
    }
  }
}

TEST(Fresnel, ConductorMatchesFresnelEquations) {
  // Gold-, aluminum- and iron-like complex indices, plus k = 0 where the
  // conductor formula must reduce to the dielectric one.
  const glm::dvec3 etas[] = {{0.18, 0.42, 1.37}, {1.35, 0.96, 0.62}, {2.87, 2.92, 2.65}, {1.5, 1.5, 1.5}};
  const glm::dvec3 ks[] = {{3.42, 2.35, 1.77}, {7.47, 6.40, 5.30}, {3.08, 2.93, 2.81}, {0, 0, 0}};
  for (int m = 0; m < 4; ++m) {
    for (double degrees : kDegrees) {
      double c = cosDegrees(degrees);
      glm::dvec3 f = rules::f64::fresnel_conductor(etas[m], ks[m], c);
      glm::vec3 f32v = rules::f32::fresnel_conductor(glm::vec3(etas[m]), glm::vec3(ks[m]), float(c));
      for (int i = 0; i < 3; ++i) {
        double reference = fresnelReference(Complex(etas[m][i], ks[m][i]), c);
        EXPECT_NEAR(f[i], reference, 1e-13) << "material " << m << " theta=" << degrees;
        EXPECT_NEAR(f32v[i], reference, 2e-6) << "material " << m << " theta=" << degrees;
      }
    }
  }
}

TEST(Fresnel, SchlickMatchesItsClosedForm) {
  // F0 + (1 - F0)(1 - cos)^5 at hand-picked cosines: exact to rounding.
  glm::dvec3 f0(0.04, 0.5, 1.0);
  EXPECT_NEAR(rules::f64::fresnel_schlick(f0, 1.0).x, 0.04, 1e-16);
  EXPECT_NEAR(rules::f64::fresnel_schlick(f0, 0.5).x, 0.04 + 0.96 / 32, 1e-16);
  EXPECT_NEAR(rules::f64::fresnel_schlick(f0, 0.0).y, 1.0, 1e-16);
  EXPECT_NEAR(rules::f64::fresnel_schlick(f0, 0.3).z, 1.0, 1e-16);
}

TEST(Fresnel, SchlickApproximatesExactDielectric) {
  // Schlick with F0 = ((eta-1)/(eta+1))^2 is exact at normal incidence and
  // at grazing; in between it errs most around 60 degrees (too low) and
  // 80-85 degrees (too high). Bounds: the worst |Schlick - exact| over eta
  // in {1.33, 1.5, 2.42} in the table of docs/shading.md, rounded up: 0.002
  // up to 30 degrees, 0.02 up to 60, 0.08 beyond.
  double worst = 0;
  for (double eta : {1.33, 1.5, 2.42}) {
    double f0 = std::pow((eta - 1) / (eta + 1), 2);
    for (double degrees : kDegrees) {
      double c = cosDegrees(degrees);
      double exact = fresnelReference(eta, c);
      double schlick = rules::f64::fresnel_schlick(glm::dvec3(f0), c).x;
      double bound = degrees == 0 ? 1e-15 : degrees <= 30 ? 0.002 : degrees <= 60 ? 0.02 : 0.08;
      EXPECT_NEAR(schlick, exact, bound) << "eta=" << eta << " theta=" << degrees;
      worst = std::max(worst, std::abs(schlick - exact));
    }
  }
  std::printf("worst |Schlick - exact dielectric|: %.4f\n", worst);
}

// Blender's metallic curve: F(0) = f0 at normal incidence, 1 at grazing,
// and for f0 = F_d(1) = 0.04 the index-1.5 dielectric itself.
TEST(Fresnel, BlenderMetallicRescalesTheIndexOnePointFiveDielectric) {
  const glm::dvec3 f0(0.04, 0.5, 0.955);
  const double normal = fresnelReference(1.5, 1.0);
  EXPECT_NEAR(normal, 0.04, 1e-15);
  for (double degrees : kDegrees) {
    const double c = cosDegrees(degrees);
    const double exact = fresnelReference(1.5, c);
    const glm::dvec3 f = rules::f64::fresnel_blender_metallic(f0, c);
    const glm::vec3 g = rules::f32::fresnel_blender_metallic(glm::vec3(f0), float(c));
    for (int i = 0; i < 3; ++i) {
      const double expected = f0[i] + (1 - f0[i]) * (exact - normal) / (1 - normal);
      EXPECT_NEAR(f[i], expected, 1e-13) << "theta=" << degrees;
      EXPECT_NEAR(g[i], expected, 2e-6) << "theta=" << degrees;
    }
    EXPECT_NEAR(f.x, exact, 1e-13) << "theta=" << degrees;
  }
  const glm::dvec3 atNormal = rules::f64::fresnel_blender_metallic(f0, 1.0), atGrazing = rules::f64::fresnel_blender_metallic(f0, 0.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(atNormal[i], f0[i], 1e-15);
    EXPECT_NEAR(atGrazing[i], 1.0, 1e-15);
  }
}

}  // namespace
}  // namespace facet::materials

// The assembled BRDF: its parts against textbook forms written differently
// (tangent form, std::erf), reciprocity, the horizon policy.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/models.h"
#include "rules/rules.h"
#include "tests/support/shading_frame.h"

namespace facet::materials {
namespace {

using facet::testing::direction;
using facet::testing::kPi;

glm::dvec3 directionInDegrees(double theta, double phi) { return direction(theta * kPi / 180, phi * kPi / 180); }

rules::f64::BrdfParams params(int d, int g, int f, double alpha) {
  rules::f64::BrdfParams p{};
  p.d_model = d;
  p.g_model = g;
  p.f_model = f;
  p.alpha = alpha;
  p.f0 = {0.95, 0.64, 0.54};
  p.eta = f == rules::f64::F_DIELECTRIC ? glm::dvec3(1.5) : glm::dvec3(0.27, 0.68, 1.22);
  p.k = {3.61, 2.63, 2.29};
  p.diffuse = {0.2, 0.3, 0.4};
  return p;
}

// Textbook forms in tan(theta) (Walter et al. 2007), independent of the
// rearranged ones in rules/shading/microfacet.h.
double textbookD(int model, double alpha, double theta) {
  double c = std::cos(theta), t2 = std::pow(std::tan(theta), 2), a2 = alpha * alpha;
  switch (model) {
    case rules::f64::D_GGX:
      return a2 / (kPi * std::pow(c, 4) * std::pow(a2 + t2, 2));
    case rules::f64::D_BECKMANN:
      return std::exp(-t2 / a2) / (kPi * a2 * std::pow(c, 4));
    default: {
      double e = 2 / a2 - 2;
      return (e + 2) / (2 * kPi) * std::pow(c, e);
    }
  }
}

double textbookLambda(int surface, double alpha, double theta) {
  double tan_theta = std::tan(theta);
  if (surface == rules::f64::D_GGX) return (-1 + std::sqrt(1 + alpha * alpha * tan_theta * tan_theta)) / 2;
  double a = 1 / (alpha * tan_theta);
  return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
}

TEST(Brdf, DistributionsMatchTextbookForms) {
  // Tolerance 1e-12 relative: rearrangements of the same expression.
  // Beckmann below exp(-80) of its peak is 0 by policy.
  for (const ModelName& d : kDistributions)
    for (double alpha : {0.05, 0.3, 1.0})
      for (double degrees : {0.0, 5.0, 20.0, 45.0, 70.0, 85.0}) {
        double theta = degrees * kPi / 180;
        double expected = textbookD(d.id, alpha, theta);
        if (d.id == rules::f64::D_BECKMANN && std::pow(std::tan(theta) / alpha, 2) >= 80) expected = 0;
        double s = std::sin(theta);
        EXPECT_NEAR(rules::f64::microfacet_D(d.id, alpha, std::cos(theta), s * s), expected, 1e-12 * expected + 1e-300)
            << d.name << " alpha=" << alpha << " theta=" << degrees;
      }
}

TEST(Brdf, SmithLambdaMatchesTextbookForms) {
  // GGX: 1e-12 relative. Beckmann: the erfc approximation's bound, 7.5e-8
  // absolute on Lambda, against std::erf.
  for (double alpha : {0.05, 0.3, 1.0})
    for (double degrees : {5.0, 30.0, 60.0, 80.0, 89.0}) {
      double theta = degrees * kPi / 180;
      double ggx = textbookLambda(rules::f64::D_GGX, alpha, theta);
      EXPECT_NEAR(rules::f64::smith_lambda(rules::f64::D_GGX, alpha, std::cos(theta)), ggx, 1e-12 * ggx + 1e-15);
      EXPECT_NEAR(rules::f64::smith_lambda(rules::f64::D_BECKMANN, alpha, std::cos(theta)),
                  textbookLambda(rules::f64::D_BECKMANN, alpha, theta), 7.5e-8)
          << "alpha=" << alpha << " theta=" << degrees;
    }
}

TEST(Brdf, AssemblesTheMicrofacetFormula) {
  // f = F G D / (4 (n.l)(n.v)) + c_diff / pi from independently built parts.
  glm::dvec3 n(0, 0, 1), l = directionInDegrees(40, 0), v = directionInDegrees(25, 150);
  rules::f64::BrdfParams p = params(rules::f64::D_GGX, rules::f64::G_SMITH_GGX_CORRELATED, rules::f64::F_SCHLICK, 0.3);
  glm::dvec3 h = glm::normalize(l + v);
  double theta_h = std::acos(h.z);
  double d = textbookD(rules::f64::D_GGX, 0.3, theta_h);
  double g = 1 / (1 + textbookLambda(rules::f64::D_GGX, 0.3, 40 * kPi / 180) +
                  textbookLambda(rules::f64::D_GGX, 0.3, 25 * kPi / 180));
  double vh = glm::dot(v, h);
  glm::dvec3 fresnel = p.f0 + (1.0 - p.f0) * std::pow(1 - vh, 5);
  glm::dvec3 expected = fresnel * d * g / (4 * l.z * v.z) + p.diffuse / kPi;
  rules::f64::BrdfTerms t = rules::f64::brdf_terms(p, n, l, v);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(t.value[i], expected[i], 1e-12 * expected[i]);
  EXPECT_NEAR(t.D, d, 1e-12 * d);
  EXPECT_NEAR(t.G, g, 1e-12);
}

TEST(Brdf, ReciprocalForEveryCombination) {
  // f(l, v) = f(v, l). Tolerance 1e-13 (double) / 1e-6 (float) relative:
  // the only asymmetry is the order of additions in 1 + L(l) + L(v).
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> theta(0, 89), phi(0, 360);
  for (const ModelName& d : kDistributions)
    for (const ModelName& g : kGeometryTerms)
      for (const ModelName& f : kFresnelTerms)
        for (double alpha : {0.0, 0.1, 0.5, 1.0})
          for (int trial = 0; trial < 20; ++trial) {
            glm::dvec3 n(0, 0, 1), l = directionInDegrees(theta(random), phi(random)), v = directionInDegrees(theta(random), phi(random));
            rules::f64::BrdfParams p = params(d.id, g.id, f.id, alpha);
            glm::dvec3 forward = rules::f64::brdf_evaluate(p, n, l, v);
            glm::dvec3 backward = rules::f64::brdf_evaluate(p, n, v, l);
            rules::f32::BrdfParams q{};
            q.d_model = d.id;
            q.g_model = g.id;
            q.f_model = f.id;
            q.alpha = float(alpha);
            q.f0 = glm::vec3(p.f0);
            q.eta = glm::vec3(p.eta);
            q.k = glm::vec3(p.k);
            q.diffuse = glm::vec3(p.diffuse);
            glm::vec3 forward32 = rules::f32::brdf_evaluate(q, glm::vec3(n), glm::vec3(l), glm::vec3(v));
            glm::vec3 backward32 = rules::f32::brdf_evaluate(q, glm::vec3(n), glm::vec3(v), glm::vec3(l));
            for (int i = 0; i < 3; ++i) {
              EXPECT_NEAR(forward[i], backward[i], 1e-13 * forward[i])
                  << d.name << "/" << g.name << "/" << f.name << " alpha=" << alpha;
              EXPECT_NEAR(forward32[i], backward32[i], 1e-6f * forward32[i])
                  << d.name << "/" << g.name << "/" << f.name << " alpha=" << alpha;
            }
          }
}

TEST(Brdf, ZeroUnderTheHorizon) {
  // Policy: n.l <= 1e-4 or n.v <= 1e-4 gives f = 0, D = G = F = 0.
  rules::f64::BrdfParams p = params(rules::f64::D_GGX, rules::f64::G_SMITH_GGX, rules::f64::F_SCHLICK, 0.5);
  glm::dvec3 n(0, 0, 1);
  for (auto [l, v] : {std::pair{directionInDegrees(100, 0), directionInDegrees(30, 0)}, std::pair{directionInDegrees(30, 0), directionInDegrees(90, 180)},
                      std::pair{directionInDegrees(89.995, 0), directionInDegrees(20, 0)}}) {
    rules::f64::BrdfTerms t = rules::f64::brdf_terms(p, n, l, v);
    EXPECT_EQ(t.value, glm::dvec3(0));
    EXPECT_EQ(t.D, 0.0);
    EXPECT_EQ(t.G, 0.0);
  }
  EXPECT_GT(rules::f64::brdf_evaluate(p, n, directionInDegrees(89.99, 0), directionInDegrees(20, 0)).x, 0.0);
}

TEST(Brdf, AlphaIsClampedToItsDocumentedRange) {
  // alpha below ALPHA_MIN evaluates as ALPHA_MIN, so alpha = 0 is a finite,
  // very sharp lobe rather than a delta.
  glm::dvec3 n(0, 0, 1), l = directionInDegrees(30, 0), v = directionInDegrees(30, 180);
  rules::f64::BrdfParams zero = params(rules::f64::D_GGX, rules::f64::G_SMITH_GGX, rules::f64::F_NONE, 0.0);
  rules::f64::BrdfParams minimum =
      params(rules::f64::D_GGX, rules::f64::G_SMITH_GGX, rules::f64::F_NONE, rules::f64::ALPHA_MIN);
  EXPECT_EQ(rules::f64::brdf_evaluate(zero, n, l, v), rules::f64::brdf_evaluate(minimum, n, l, v));
  EXPECT_NEAR(rules::f64::brdf_terms(zero, n, l, v).D, 1 / (kPi * 1e-6), 1e-3);
}

}  // namespace
}  // namespace facet::materials

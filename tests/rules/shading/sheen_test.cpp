// The sheen (rules/shading/sheen.h): a material without one takes the bare
// base's code path bit for bit, the layered BRDF is reciprocal, and the
// albedo entry the table is built from agrees with an independent
// quadrature of the lobe.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "materials/albedo.h"
#include "rules/rules.h"

namespace facet::materials {
namespace {

namespace m = rules::f64;
constexpr double kPi = std::numbers::pi;
const glm::dvec3 kN(0, 0, 1);

glm::dvec3 direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// A Beckmann dielectric base with a diffuse lobe (the coat's tests take GGX).
m::BrdfParams base() {
  m::BrdfParams p{};
  p.d_model = m::D_BECKMANN;
  p.g_model = m::G_SMITH_BECKMANN_CORRELATED;
  p.f_model = m::F_DIELECTRIC;
  p.alpha = 0.3;
  p.eta = glm::dvec3(1.5);
  p.diffuse = {0.5, 0.05, 0.1};
  p.clearcoat_normal = kN;
  return p;
}

// E(mu) of the lobe for color 1: Gauss-Legendre in cos(theta_l) and in
// azimuth, dense enough for the smoothest sheen's grazing peak. Independent
// of the table's Hammersley sum and cosine sampler.
double quadratureAlbedo(double alpha, double mu) {
  static const QuadratureRule polar = gaussLegendre01(384), azimuth = gaussLegendre01(256);
  const glm::dvec3 v(std::sqrt(1 - mu * mu), 0, mu);
  double sum = 0;
  for (std::size_t i = 0; i < polar.nodes.size(); ++i) {
    const double cos_l = polar.nodes[i];
    const double sin_l = std::sqrt(1 - cos_l * cos_l);
    double ring = 0;
    // The lobe is symmetric about v's plane: phi over [0, pi], twice.
    for (std::size_t j = 0; j < azimuth.nodes.size(); ++j) {
      const double phi = kPi * azimuth.nodes[j];
      const glm::dvec3 l(sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l);
      ring += azimuth.weights[j] * m::sheen_lobe(alpha, kN, l, v);
    }
    sum += polar.weights[i] * 2 * kPi * ring * cos_l;
  }
  return sum;
}

TEST(Sheen, WithoutASheenTheBaseIsUnchangedBitForBit) {
  // Color 0 with any roughness and any albedos: the same bits as the bare
  // base for f, the lobe sampler and its density.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const m::BrdfParams p = base();
    const m::SheenParams s{glm::dvec3(0.0), uniform(random)};
    const glm::dvec3 n = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 1));
    const glm::dvec3 v = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 0.5));
    const glm::dvec2 u(uniform(random), uniform(random));
    const double e_v = uniform(random), e_l = uniform(random);
    const glm::dvec3 l = m::sample_sheen_lobes(p, s, n, v, e_v, u);
    const glm::dvec3 scale(1.0, 1.1, 1.2);
    EXPECT_EQ(l, m::sample_brdf_lobes(p, n, v, u));
    EXPECT_EQ(m::sheen_lobes_pdf(p, s, n, l, v, e_v), m::brdf_lobes_pdf(p, n, l, v));
    EXPECT_EQ(m::sheen_evaluate(p, s, n, l, v, scale, e_v, e_l), m::brdf_evaluate_scaled(p, n, l, v, scale));
  }
}

TEST(Sheen, TheLayeredBrdfIsReciprocal) {
  // With each direction's albedo looked up for it, f(l, v) = f(v, l): the
  // layering takes the larger of the two albedos, the lobe is symmetric.
  std::mt19937 random(9);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2 * kPi), unit(0.0, 1.0);
  for (double alpha : {0.0, 0.09, 0.5, 1.0})
    for (int trial = 0; trial < 100; ++trial) {
      const m::SheenParams s{glm::dvec3(0.9, 0.4, 0.2), alpha};
      const glm::dvec3 l = direction(theta(random), phi(random)), v = direction(theta(random), phi(random));
      const double e_l = 1.2 * unit(random), e_v = 1.2 * unit(random);
      const glm::dvec3 forward = m::sheen_evaluate(base(), s, kN, l, v, glm::dvec3(1.0), e_v, e_l);
      const glm::dvec3 backward = m::sheen_evaluate(base(), s, kN, v, l, glm::dvec3(1.0), e_l, e_v);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(forward[c], backward[c], 1e-12 * std::max(1.0, forward[c]));
    }
}

TEST(Sheen, TheAlbedoEntryMatchesAnIndependentQuadrature) {
  // The table's entry (4096 Hammersley points of the cosine sampler, as the
  // renderers build it) against Gauss-Legendre: within 2% of the value or
  // 0.005 absolute, the smoothest sheen at grazing views being the worst.
  double worst = 0;
  for (double roughness : {0.1, 0.4, 1.0})
    for (double mu : {0.1, 0.4, 1.0}) {
      const double alpha = roughness * roughness;
      const double entry = m::sheen_albedo_entry(mu, alpha, 4096).x, quadrature = quadratureAlbedo(alpha, mu);
      EXPECT_NEAR(entry, quadrature, std::max(0.005, 0.02 * quadrature)) << "roughness " << roughness << " mu " << mu;
      worst = std::max(worst, std::abs(entry - quadrature));
      std::printf("sheen roughness %.1f, mu %.1f: entry %.5f, quadrature %.5f\n", roughness, mu, entry, quadrature);
    }
  std::printf("sheen albedo: largest |entry - quadrature| %.2g\n", worst);
}

TEST(Sheen, TheSmoothSheenGlowsAtGrazingAndFadesHeadOn) {
  // Velvet's look: a grazing view sees far more sheen than a head-on one.
  const double alpha = 0.09;
  EXPECT_GT(m::sheen_albedo_entry(0.1, alpha, 1024).x, 5 * m::sheen_albedo_entry(0.9, alpha, 1024).x);
  // No sheen under the horizon policy.
  EXPECT_EQ(m::sheen_lobe(alpha, kN, direction(1.0, 0.0), direction(1.6, kPi)), 0.0);
}

}  // namespace
}  // namespace facet::materials

// The clear coat (rules/shading/clearcoat.h, lobe_sampling.h): a material
// without one takes the bare base's code path bit for bit, the layered BRDF
// is reciprocal, the coat alone and over a white base never gains energy,
// and facet albedo's quadrature of the coat agrees with an independent one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/albedo.h"
#include "rules/rules.h"
#include "tests/support/shading_frame.h"
#include "tests/support/brdf_params.h"
#include "tests/support/quadrature.h"

namespace facet::materials {
namespace {

using facet::testing::kPi;
using facet::testing::kN;
using facet::testing::direction;
namespace m = rules::f64;
using testing::integratePolar;

// A rough dielectric base with a diffuse lobe, under a coat.
m::BrdfParams coatedBase(double clearcoat, double coat_alpha) {
  m::BrdfParams p = facet::testing::schlickBase(0.4, glm::dvec3(0.04), {0.6, 0.3, 0.1});
  p.clearcoat = clearcoat;
  p.clearcoat_alpha = coat_alpha;
  return p;
}

// A base that reflects nothing (a dielectric of index 1: no interface) and
// diffuses `diffuse`, under a full coat of alpha `coat_alpha`.
m::BrdfParams overBlack(double coat_alpha, double diffuse = 0.0) {
  m::BrdfParams p = coatedBase(1.0, coat_alpha);
  p.f_model = m::F_DIELECTRIC;
  p.eta = glm::dvec3(1.0);
  p.diffuse = glm::dvec3(diffuse);
  return p;
}

TEST(Clearcoat, WithoutACoatTheBaseIsUnchangedBitForBit) {
  // clearcoat 0 with any coat roughness and normal: the same bits as the
  // bare base for f, the lobe sampler and its density.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    m::BrdfParams p = coatedBase(0.0, uniform(random));
    p.clearcoat_normal = glm::normalize(glm::dvec3(uniform(random), uniform(random), 1));
    const glm::dvec3 n = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 1));
    const glm::dvec3 v = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 0.5));
    const glm::dvec2 u(uniform(random), uniform(random));
    const glm::dvec3 l = m::sample_brdf_lobes(p, n, v, u);
    EXPECT_EQ(l, m::sample_base_lobes(p, n, v, u));
    EXPECT_EQ(m::brdf_lobes_pdf(p, n, l, v), m::base_lobes_pdf(p, n, l, v));
    EXPECT_EQ(m::brdf_evaluate(p, n, l, v), m::brdf_terms(p, n, l, v).value);
    EXPECT_EQ(m::opaque_continuation_lobe(p, n, v, u),
              u.x < m::specular_lobe_probability(p) ? m::PATH_LOBE_GLOSSY : m::PATH_LOBE_DIFFUSE);
  }
}

TEST(Clearcoat, TheLayeredBrdfIsReciprocal) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2 * kPi);
  for (double coat_alpha : {0.01, 0.1, 0.6})
    for (int trial = 0; trial < 100; ++trial) {
      const m::BrdfParams p = coatedBase(0.7, coat_alpha);
      const glm::dvec3 l = direction(theta(random), phi(random)), v = direction(theta(random), phi(random));
      const glm::dvec3 forward = m::brdf_evaluate(p, kN, l, v), backward = m::brdf_evaluate(p, kN, v, l);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(forward[c], backward[c], 1e-12 * std::max(1.0, forward[c]));
    }
}

// E(mu) of p's whole BRDF by a polar quadrature of l about the mirror
// direction's pole: panels on theta_l sized for the coat's alpha, 256
// Gauss-Legendre nodes in azimuth. Independent of facet albedo's map.
double polarAlbedo(const m::BrdfParams& p, double mu) {
  static const QuadratureRule azimuth = gaussLegendre01(256);
  const glm::dvec3 v(std::sqrt(1 - mu * mu), 0, mu);
  const glm::dvec3 r = glm::reflect(-v, kN);
  // A frame about r, in which the peaked coat lobe sits at the pole.
  const glm::dvec3 t = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), r)), b = glm::cross(r, t);
  return integratePolar(std::max(p.clearcoat_alpha, 0.02),
                        [&](double theta) {
                          double sum = 0;
                          for (size_t j = 0; j < azimuth.nodes.size(); ++j) {
                            const double phi = 2 * kPi * azimuth.nodes[j];
                            const glm::dvec3 l =
                                std::cos(theta) * r + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
                            if (l.z > 0) sum += azimuth.weights[j] * m::brdf_evaluate(p, kN, l, v).x * l.z;
                          }
                          return 2 * kPi * sum * std::sin(theta);
                        }) +
         // integratePolar covers theta up to pi/2; the rest of the sphere
         // about r (a grazing view's hemisphere reaches past it) in one more
         // Gauss-Legendre panel.
         [&] {
           static const QuadratureRule polar = gaussLegendre01(64);
           double sum = 0;
           for (size_t i = 0; i < polar.nodes.size(); ++i) {
             const double theta = kPi / 2 + kPi / 2 * polar.nodes[i];
             double ring = 0;
             for (size_t j = 0; j < azimuth.nodes.size(); ++j) {
               const double phi = 2 * kPi * azimuth.nodes[j];
               const glm::dvec3 l = std::cos(theta) * r + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
               if (l.z > 0) ring += azimuth.weights[j] * m::brdf_evaluate(p, kN, l, v).x * l.z;
             }
             sum += polar.weights[i] * 2 * kPi * ring * std::sin(theta) * kPi / 2;
           }
           return sum;
         }();
}

TEST(Clearcoat, WhiteFurnaceOfTheCoatMatchesFacetAlbedosQuadrature) {
  // The coat over a black base reflects c F E_coat <= 1. facet albedo's
  // value (the coat through its own sampler's square) against the polar
  // quadrature: within 1e-5 (the polar rule cut at the horizon, l.z > 0).
  double highest = 0, worst = 0;
  for (double coat_alpha : {0.05, 0.2, 0.6})
    for (double mu : {0.2, 0.6, 1.0}) {
      const m::BrdfParams p = overBlack(coat_alpha);
      const AlbedoResult albedo = directionalAlbedo(p, mu, 256);
      EXPECT_LT(albedo.specular.x, 1e-12);  // the base of index 1 reflects nothing
      EXPECT_LE(albedo.albedo.x, 1 + albedo.error_estimate);
      EXPECT_GT(albedo.coat.x, 0.0);
      const double polar = polarAlbedo(p, mu);
      EXPECT_NEAR(albedo.albedo.x, polar, 1e-5) << "alpha " << coat_alpha << " mu " << mu;
      highest = std::max(highest, albedo.albedo.x);
      worst = std::max(worst, std::abs(albedo.albedo.x - polar));
      std::printf("coat alpha %.2f over black, mu %.1f: facet albedo %.7f, polar quadrature %.7f\n", coat_alpha, mu,
                  albedo.albedo.x, polar);
    }
  std::printf("coat over black: highest E %.6f, largest |albedo - polar quadrature| %.2g\n", highest, worst);
}

TEST(Clearcoat, OverAWhiteBaseTheLayersNeverGainEnergy) {
  // A white Lambert base (albedo 1) under a full coat: each crossing keeps
  // 1 - F of the light, so coat and base together reflect at most 1.
  double highest = 0;
  for (double coat_alpha : {0.02, 0.3})
    for (double mu : {0.05, 0.3, 0.7, 1.0}) {
      const AlbedoResult albedo = directionalAlbedo(overBlack(coat_alpha, 1.0), mu, 256);
      EXPECT_LE(albedo.albedo.x, 1 + albedo.error_estimate) << "alpha " << coat_alpha << " mu " << mu;
      EXPECT_GT(albedo.albedo.x, 0.3);  // at grazing v the coat reflects most, and a rough one loses much
      highest = std::max(highest, albedo.albedo.x);
      std::printf("coat alpha %.2f over white Lambert, mu %.2f: E %.6f\n", coat_alpha, mu, albedo.albedo.x);
    }
}

TEST(Clearcoat, ASmoothCoatAddsASharperHighlight) {
  // On a rough base, a smooth coat raises the mirror direction's value far
  // above the base's own lobe, and leaves directions off the mirror near
  // the base's value attenuated by the coat (< the bare base).
  const glm::dvec3 v = direction(0.5, 0.0), mirror = glm::reflect(-v, kN), off = direction(0.9, kPi);
  const m::BrdfParams bare = coatedBase(0.0, 0.0), coated = coatedBase(1.0, 0.0025);
  EXPECT_GT(m::brdf_evaluate(coated, kN, mirror, v).x, 10 * m::brdf_evaluate(bare, kN, mirror, v).x);
  EXPECT_LT(m::brdf_evaluate(coated, kN, off, v).x, m::brdf_evaluate(bare, kN, off, v).x);
  EXPECT_GT(m::brdf_evaluate(coated, kN, off, v).x, 0.85 * m::brdf_evaluate(bare, kN, off, v).x);
}

}  // namespace
}  // namespace facet::materials

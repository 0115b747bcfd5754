// The sheen (rules/shading/sheen.h): a material without one takes the bare
// base's code path bit for bit, the layered BRDF is reciprocal, its albedo's
// entries and knots agree with an independent quadrature of the lobe, and
// the sheen alone and over a white base never gains energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>
#include <vector>
#include <algorithm>

#include "materials/albedo.h"
#include "materials/material.h"
#include "rules/rules.h"
#include "tests/support/shading_frame.h"

namespace facet::materials {
namespace {

using facet::testing::kPi;
using facet::testing::kN;
using facet::testing::direction;
namespace m = rules::f64;

// A Beckmann dielectric base of diffuse `diffuse` under a sheen of `color`
// and `roughness`, its knots as materials give them.
m::BrdfParams sheened(glm::dvec3 color, double roughness, glm::dvec3 diffuse = {0.5, 0.05, 0.1}, double ior = 1.5) {
  Material material;
  material.distribution = m::D_BECKMANN;
  material.geometry = m::G_SMITH_BECKMANN_CORRELATED;
  material.fresnel = m::F_DIELECTRIC;
  material.alpha = 0.3;
  material.eta = glm::dvec3(ior);
  material.diffuse = diffuse;
  material.sheenColor = color;
  material.sheenRoughness = roughness;
  return toParams64(material);
}

// E(mu) of p's whole BRDF (red channel) by Gauss-Legendre over l.
double furnace(const m::BrdfParams& p, double mu) {
  static const QuadratureRule polar = gaussLegendre01(128), azimuth = gaussLegendre01(96);
  const glm::dvec3 v(std::sqrt(1 - mu * mu), 0, mu);
  double sum = 0;
  for (std::size_t i = 0; i < polar.nodes.size(); ++i) {
    const double cos_l = polar.nodes[i], sin_l = std::sqrt(1 - cos_l * cos_l);
    double ring = 0;
    for (std::size_t j = 0; j < azimuth.nodes.size(); ++j) {
      const double phi = kPi * azimuth.nodes[j];
      ring += azimuth.weights[j] * m::brdf_evaluate(p, kN, {sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l}, v).x;
    }
    sum += polar.weights[i] * 2 * kPi * ring * cos_l;
  }
  return sum;
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
  // Color 0 with any roughness and knots: the same bits as the base alone
  // for f, the lobe sampler, its density and the split sum.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    m::BrdfParams p = sheened(glm::dvec3(0.0), uniform(random)), bare = p;
    EXPECT_EQ(p.sheen_albedo_near, glm::dvec4(0.0));  // no knots are computed without a sheen
    p.sheen_alpha = uniform(random);
    p.sheen_albedo_near = glm::dvec4(uniform(random));
    p.sheen_albedo_far = glm::dvec4(uniform(random));
    const glm::dvec3 n = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 1));
    const glm::dvec3 v = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 0.5));
    const glm::dvec2 u(uniform(random), uniform(random));
    const glm::dvec3 l = m::sample_brdf_lobes(p, n, v, u), scale(1.0, 1.1, 1.2);
    EXPECT_EQ(l, m::sample_brdf_lobes(bare, n, v, u));
    EXPECT_EQ(m::brdf_lobes_pdf(p, n, l, v), m::brdf_lobes_pdf(bare, n, l, v));
    const m::BrdfTerms t = m::brdf_terms(p, n, l, v);
    EXPECT_EQ(m::brdf_evaluate_scaled(p, n, l, v, scale), t.specular * scale + t.diffuse);
    EXPECT_EQ(m::opaque_continuation_lobe(p, n, v, u), m::opaque_continuation_lobe(bare, n, v, u));
    const glm::dvec3 light(0.7, 0.8, 0.9);
    EXPECT_EQ(m::split_sum(p, 0.6, light, {0.5, 0.1}, light, scale),
              m::split_sum(bare, 0.6, light, {0.5, 0.1}, light, scale));
  }
}

TEST(Sheen, TheLayeredBrdfIsReciprocal) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2 * kPi);
  for (double roughness : {0.0, 0.3, 0.7, 1.0}) {
    const m::BrdfParams p = sheened({0.9, 0.4, 0.2}, roughness);
    for (int trial = 0; trial < 100; ++trial) {
      const glm::dvec3 l = direction(theta(random), phi(random)), v = direction(theta(random), phi(random));
      const glm::dvec3 forward = m::brdf_evaluate(p, kN, l, v), backward = m::brdf_evaluate(p, kN, v, l);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(forward[c], backward[c], 1e-12 * std::max(1.0, forward[c]));
    }
  }
}

TEST(Sheen, TheAlbedoEntryMatchesAnIndependentQuadrature) {
  // An entry (Hammersley points of the cosine sampler) against
  // Gauss-Legendre: within 2% of the value or 0.005 absolute, the smoothest
  // sheen at grazing views being the worst.
  double worst = 0;
  for (double roughness : {0.1, 0.4, 1.0})
    for (double mu : {0.1, 0.4, 1.0}) {
      const double alpha = roughness * roughness;
      const double entry = m::sheen_albedo_entry(mu, alpha, 2048).x, quadrature = quadratureAlbedo(alpha, mu);
      EXPECT_NEAR(entry, quadrature, std::max(0.005, 0.02 * quadrature)) << "roughness " << roughness << " mu " << mu;
      worst = std::max(worst, std::abs(entry - quadrature));
      std::printf("sheen roughness %.1f, mu %.1f: entry %.5f, quadrature %.5f\n", roughness, mu, entry, quadrature);
    }
  std::printf("sheen albedo: largest |entry - quadrature| %.2g\n", worst);
}

TEST(Sheen, TheKnotsFollowTheAlbedoBetweenThem) {
  // Read between the knots (linearly) against the entry itself, both
  // clamped at 1 as the layering takes them: within 0.05 for the smoothest
  // sheen, whose albedo falls from above 1 to almost 0 between n.v = 0.05
  // and 0.2, and within 0.015 from roughness 0.3 up.
  for (double roughness : {0.07, 0.3, 0.6, 1.0}) {
    const m::BrdfParams p = sheened(glm::dvec3(1.0), roughness);
    double worst = 0;
    for (double mu : {0.03, 0.06, 0.11, 0.17, 0.25, 0.4, 0.62, 0.85}) {
      const double read = std::min(m::sheen_albedo(p, mu), 1.0);
      const double entry = std::min(m::sheen_albedo_entry(mu, p.sheen_alpha, 2048).x, 1.0);
      EXPECT_NEAR(read, entry, roughness < 0.3 ? 0.05 : 0.015) << "roughness " << roughness << " mu " << mu;
      worst = std::max(worst, std::abs(read - entry));
    }
    std::printf("sheen roughness %.2f: largest |knots - entry| %.3g\n", roughness, worst);
  }
}

TEST(Sheen, WhiteFurnaceStaysAtMostOne) {
  // A white sheen alone (over a base of index 1 that diffuses nothing)
  // reflects at most min(E, 1); over a white Lambert base the two together
  // at most 1 (within the quadrature's and the knots' error). The split sum
  // under a uniform white environment and facet albedo against the same
  // integral.
  double highest_alone = 0, highest_white = 0, worst_split = 0, worst_albedo = 0;
  for (double roughness : {0.07, 0.3, 0.6, 1.0})
    for (double mu : {0.05, 0.2, 0.5, 1.0}) {
      const double alone = furnace(sheened(glm::dvec3(1.0), roughness, glm::dvec3(0.0), 1.0), mu);
      const m::BrdfParams white_base = sheened(glm::dvec3(1.0), roughness, glm::dvec3(1.0), 1.0);
      const double white = furnace(white_base, mu);
      EXPECT_LE(alone, 1.0 + 1e-2) << "roughness " << roughness << " mu " << mu;
      EXPECT_LE(white, 1.0 + 1e-2) << "roughness " << roughness << " mu " << mu;
      EXPECT_GT(white, 0.6) << "roughness " << roughness << " mu " << mu;
      const double split =
          m::split_sum(white_base, mu, glm::dvec3(1.0), {0.0, 0.0}, glm::dvec3(1.0), glm::dvec3(1.0)).x;
      worst_split = std::max(worst_split, std::abs(split - white));
      // facet albedo's quadrature (the sheen through the cosine map) agrees.
      const AlbedoResult albedo = directionalAlbedo(white_base, mu, 128);
      EXPECT_NEAR(albedo.albedo.x, white, 5e-3) << "roughness " << roughness << " mu " << mu;
      EXPECT_GT(albedo.sheen.x, 0.0);
      worst_albedo = std::max(worst_albedo, std::abs(albedo.albedo.x - white));
      highest_alone = std::max(highest_alone, alone);
      highest_white = std::max(highest_white, white);
      std::printf("sheen roughness %.2f mu %.2f: alone %.5f, over white Lambert %.5f, split sum %.5f\n", roughness, mu,
                  alone, white, split);
    }
  std::printf(
      "sheen furnace: highest alone %.5f, over white %.5f; largest |split sum - furnace| %.3g, |facet "
      "albedo - furnace| %.3g\n",
      highest_alone, highest_white, worst_split, worst_albedo);
}

TEST(Sheen, TheSmoothSheenGlowsAtGrazingAndFadesHeadOn) {
  // Velvet's look: a grazing view sees far more sheen than a head-on one.
  const m::BrdfParams p = sheened(glm::dvec3(1.0), 0.3);
  EXPECT_GT(m::sheen_albedo(p, 0.1), 5 * m::sheen_albedo(p, 0.9));
  // No sheen under the horizon policy.
  EXPECT_EQ(m::sheen_lobe(0.09, kN, direction(1.0, 0.0), direction(1.6, kPi)), 0.0);
}

// A sheen whose roughness is textured reads its knots between the rows
// about its alpha: at a row's own alpha they are that row, and at 201
// roughnesses across [0, 1] (below the smallest alpha, at the rows and
// between them) within 0.0025 of the knots tabulated at the alpha itself.
TEST(Sheen, KnotsReadBetweenTheRowsFollowTheKnotsAtTheAlpha) {
  const std::vector<glm::dvec4>& rows = sheenAlbedoRows();
  ASSERT_EQ(rows.size(), std::size_t(2 * m::SHEEN_ROWS));
  const auto between = [&](double alpha) {
    const m::SheenRows at = m::sheen_rows_at(alpha);
    const std::size_t first = 2 * std::size_t(at.first);
    return std::pair{glm::mix(rows[first], rows[first + 2], at.weight),
                     glm::mix(rows[first + 1], rows[first + 3], at.weight)};
  };
  for (const int j : {0, 7, 32}) {
    const m::SheenRows at = m::sheen_rows_at(m::sheen_row_alpha(j));
    EXPECT_NEAR(double(at.first) + at.weight, double(j), 1e-9);
  }
  double worst = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const double roughness = i / 200.0, alpha = roughness * roughness;
    const auto [near, far] = between(alpha);
    const glm::dvec4 exactNear = m::sheen_albedo_knots(alpha, 0, 2048),
                     exactFar = m::sheen_albedo_knots(alpha, 4, 2048);
    for (int k = 0; k < 4; ++k)
      worst = std::max({worst, std::abs(near[k] - exactNear[k]), std::abs(far[k] - exactFar[k])});
  }
  std::printf("worst knot read between rows: %.5f\n", worst);
  EXPECT_LT(worst, 0.0025);
}

}  // namespace
}  // namespace facet::materials

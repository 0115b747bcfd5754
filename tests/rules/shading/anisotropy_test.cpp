// The anisotropic lobe (rules/shading/microfacet.h, brdf.h, brdf_sampling.h):
// its D and Smith Lambda against their defining integrals, the isotropic
// formulas as the special case, reciprocity, the white furnace, and the
// isotropic path untouched by the tangent.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/albedo.h"
#include "rules/rules.h"
#include "tests/support/shading_frame.h"
#include "tests/support/quadrature.h"

namespace facet::materials {
namespace {

using facet::testing::kPi;
using facet::testing::direction;
namespace m = rules::f64;
using testing::integratePolar;
// (alpha_t, alpha_b) pairs: strongly and mildly anisotropic, either way round.
const glm::dvec2 kAnisotropicAlphas[] = {{0.5, 0.1}, {0.1, 0.5}, {1.0, 0.25}, {0.3, 0.2}};

// Integral over the hemisphere of m of integrand(m), polar panels sized for
// the narrower alpha, 128 Gauss-Legendre nodes in azimuth.
template <class Integrand>
double hemisphere(glm::dvec2 alpha, const Integrand& integrand) {
  static const QuadratureRule azimuth = gaussLegendre01(128);
  return integratePolar(std::min(alpha.x, alpha.y), [&](double theta) {
    double sum = 0;
    for (size_t j = 0; j < azimuth.nodes.size(); ++j)
      sum += azimuth.weights[j] * integrand(direction(theta, 2 * kPi * azimuth.nodes[j]));
    return 2 * kPi * sum * std::sin(theta);
  });
}

TEST(Anisotropy, DistributionsAreNormalized) {
  // Tolerance 1e-6: the azimuthal rule resolves an elongation of 10 to ~1e-9.
  for (int d : {m::D_GGX, m::D_BECKMANN})
    for (glm::dvec2 alpha : kAnisotropicAlphas) {
      double area = hemisphere(alpha, [&](glm::dvec3 w) { return m::microfacet_D_anisotropic(d, alpha, w) * w.z; });
      EXPECT_NEAR(area, 1.0, 1e-6) << "d " << d << " alpha " << alpha.x << "," << alpha.y;
    }
}

TEST(Anisotropy, SmithLambdaMakesTheVisibleProjectedAreaTheCosine) {
  // G1(v) integral of max(0, v.m) D(m) dm = n.v defines Lambda (Heitz 2014,
  // eq. 18); anisotropic, v at azimuths between the axes. Tolerance 1e-5,
  // 5e-4 at grazing v, where the kink of max(0, v.m) cuts across the
  // azimuthal rule's nodes.
  for (int d : {m::D_GGX, m::D_BECKMANN})
    for (glm::dvec2 alpha : kAnisotropicAlphas)
      for (double theta_v : {0.0, 0.5, 1.0, 1.3, 1.5})
        for (double phi_v : {0.0, 0.7, 2.0}) {
          glm::dvec3 v = direction(theta_v, phi_v);
          double visible = hemisphere(alpha, [&](glm::dvec3 w) {
            return std::max(0.0, glm::dot(v, w)) * m::microfacet_D_anisotropic(d, alpha, w);
          });
          double g1 = 1 / (1 + m::smith_lambda_anisotropic(d, alpha, v));
          EXPECT_NEAR(g1 * visible / v.z, 1.0, theta_v < 1.2 ? 1e-5 : 5e-4)
              << "d " << d << " alpha " << alpha.x << "," << alpha.y << " theta " << theta_v << " phi " << phi_v;
        }
}

TEST(Anisotropy, EqualRoughnessesAreTheIsotropicFormulas) {
  for (int d : {m::D_GGX, m::D_BECKMANN})
    for (double alpha : {0.05, 0.3, 1.0})
      for (double theta : {0.0, 0.2, 0.8, 1.4})
        for (double phi : {0.0, 1.0, 2.5}) {
          glm::dvec3 w = direction(theta, phi);
          double s2 = std::sin(theta) * std::sin(theta);
          double isotropic = m::microfacet_D(d, alpha, w.z, s2);
          EXPECT_NEAR(m::microfacet_D_anisotropic(d, {alpha, alpha}, w), isotropic, 1e-12 * std::max(1.0, isotropic));
          EXPECT_NEAR(m::smith_lambda_anisotropic(d, {alpha, alpha}, w), m::smith_lambda(d, alpha, w.z), 1e-12);
        }
  // KHR_materials_anisotropy's mapping.
  EXPECT_EQ(m::anisotropic_alpha(0.2, 0.0), glm::dvec2(0.2, 0.2));
  EXPECT_EQ(m::anisotropic_alpha(0.2, 1.0), glm::dvec2(1.0, 0.2));
  EXPECT_NEAR(m::anisotropic_alpha(0.2, 0.5).x, 0.2 + 0.8 * 0.25, 1e-15);
}

m::BrdfParams anisotropic(int d, int g, double alpha, double anisotropy, glm::dvec3 tangent) {
  m::BrdfParams p{};
  p.d_model = d;
  p.g_model = g;
  p.f_model = m::F_SCHLICK;
  p.alpha = alpha;
  p.f0 = {0.9, 0.7, 0.5};
  p.diffuse = {0.1, 0.2, 0.3};
  p.anisotropy = anisotropy;
  p.tangent = tangent;
  return p;
}

TEST(Anisotropy, ReciprocalAndElongatedAlongTheTangent) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2 * kPi);
  const glm::dvec3 n(0, 0, 1), tangent(std::cos(0.4), std::sin(0.4), 0);
  for (int g : {m::G_SMITH_GGX, m::G_SMITH_GGX_CORRELATED, m::G_SMITH_BECKMANN_CORRELATED, m::G_KELEMEN})
    for (int trial = 0; trial < 50; ++trial) {
      m::BrdfParams p = anisotropic(g >= m::G_SMITH_BECKMANN ? m::D_BECKMANN : m::D_GGX, g, 0.1, 0.8, tangent);
      glm::dvec3 l = direction(theta(random), phi(random)), v = direction(theta(random), phi(random));
      glm::dvec3 forward = m::brdf_evaluate(p, n, l, v), backward = m::brdf_evaluate(p, n, v, l);
      EXPECT_NEAR(forward.x, backward.x, 1e-12 * std::max(1.0, forward.x)) << "g " << g;
    }
  // The highlight: turning the half vector 0.3 rad towards the tangent loses
  // less than turning it towards the bitangent (alpha_t > alpha_b).
  m::BrdfParams p = anisotropic(m::D_GGX, m::G_SMITH_GGX_CORRELATED, 0.05, 0.8, tangent);
  const glm::dvec3 bitangent = glm::cross(n, tangent), v = glm::normalize(glm::dvec3(0.1, 0.2, 1));
  auto at_half = [&](glm::dvec3 h) { return m::brdf_terms(p, n, glm::reflect(-v, h), v).D; };
  EXPECT_GT(at_half(glm::normalize(n + 0.3 * tangent)), 10 * at_half(glm::normalize(n + 0.3 * bitangent)));
}

TEST(Anisotropy, IsotropicPathIgnoresTheTangent) {
  // anisotropy 0 takes the isotropic code path: any tangent gives the same
  // bits for f, the samplers and their densities.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, -0.3, 1));
  for (int d : {m::D_GGX, m::D_BECKMANN})
    for (int trial = 0; trial < 100; ++trial) {
      m::BrdfParams a = anisotropic(d, m::G_SMITH_GGX_CORRELATED, 0.2, 0.0, {1, 0, 0});
      m::BrdfParams b = anisotropic(d, m::G_SMITH_GGX_CORRELATED, 0.2, 0.0,
                                    glm::normalize(glm::dvec3(uniform(random), uniform(random), 1)));
      glm::dvec3 v = glm::normalize(glm::dvec3(uniform(random) - 0.5, uniform(random) - 0.5, 1));
      glm::dvec2 u(uniform(random), uniform(random));
      for (int technique : {m::SAMPLE_D, m::SAMPLE_GGX_VISIBLE}) {
        glm::dvec3 l = m::sample_direction(technique, a, n, v, u);
        EXPECT_EQ(l, m::sample_direction(technique, b, n, v, u));
        EXPECT_EQ(m::direction_pdf(technique, a, n, l, v), m::direction_pdf(technique, b, n, l, v));
        EXPECT_EQ(m::brdf_evaluate(a, n, l, v), m::brdf_evaluate(b, n, l, v));
      }
      EXPECT_EQ(m::anisotropic_bent_normal(b, n, v), n);
    }
}

// E(mu) with F = 1 by Gauss-Legendre over the sampler's unit square: the
// integrand f (n.l) / pdf is G2 / G1(v) for visible normals, smooth but for
// the horizon's kink. Returns E.
double furnace(int d, int g, glm::dvec2 alpha_strength, double mu, double phi_v, int nodes) {
  m::BrdfParams p = anisotropic(d, g, alpha_strength.x, alpha_strength.y, {1, 0, 0});
  p.f_model = m::F_NONE;
  p.diffuse = glm::dvec3(0);
  const glm::dvec3 n(0, 0, 1), v = direction(std::acos(mu), phi_v);
  const QuadratureRule rule = gaussLegendre01(nodes);
  const int technique = m::specular_technique(p);
  double sum = 0;
  for (int i = 0; i < nodes; ++i)
    for (int j = 0; j < nodes; ++j) {
      glm::dvec3 l = m::sample_direction(technique, p, n, v, {rule.nodes[i], rule.nodes[j]});
      double pdf = m::direction_pdf(technique, p, n, l, v);
      if (pdf > 0) sum += rule.weights[i] * rule.weights[j] * m::brdf_evaluate(p, n, l, v).x * l.z / pdf;
    }
  return sum;
}

// At alpha 1 KHR_materials_anisotropy's mapping leaves the lobe round
// (alpha_t = mix(1, 1, s^2) = alpha_b): any strength then shades as none,
// the split sum's bent normal included. Below it the bend grows with the
// lobe's elongation.
TEST(Anisotropy, AFullyRoughLobeIsRoundAtAnyStrength) {
  const glm::dvec3 n(0, 0, 1), t = glm::normalize(glm::dvec3(1, 0.3, 0));
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.3, -0.5, 0.6)), l = glm::normalize(glm::dvec3(-0.2, 0.4, 0.8));
  const m::BrdfParams round = anisotropic(m::D_GGX, m::G_SMITH_GGX_CORRELATED, 1.0, 0.0, t);
  for (double strength : {0.3, 1.0}) {
    const m::BrdfParams p = anisotropic(m::D_GGX, m::G_SMITH_GGX_CORRELATED, 1.0, strength, t);
    EXPECT_NEAR(glm::length(m::anisotropic_bent_normal(p, n, v) - n), 0.0, 1e-15) << strength;
    EXPECT_NEAR(glm::length(m::brdf_evaluate(p, n, l, v) - m::brdf_evaluate(round, n, l, v)), 0.0, 1e-12);
    EXPECT_EQ(m::isotropic_equivalent_alpha(p), 1.0);
  }
  double previous = 0.0;
  for (double strength : {0.3, 0.6, 1.0}) {
    const m::BrdfParams p = anisotropic(m::D_GGX, m::G_SMITH_GGX_CORRELATED, 0.09, strength, t);
    const double bent = glm::length(m::anisotropic_bent_normal(p, n, v) - n);
    EXPECT_GT(bent, previous) << strength;
    previous = bent;
  }
}

TEST(Anisotropy, WhiteFurnaceLosesEnergyAndNeverGainsIt) {
  // Single scattering with F = 1 reflects at most everything: E <= 1 within
  // the quadrature's error (its change from 128 to 256 nodes, plus 1e-4).
  double highest = 0;
  for (int d : {m::D_GGX, m::D_BECKMANN})
    for (glm::dvec2 alpha_strength : {glm::dvec2(0.01, 0.9), glm::dvec2(0.1, 0.5), glm::dvec2(0.3, 1.0)})
      for (double mu : {0.1, 0.5, 1.0})
        for (double phi_v : {0.0, 0.8, kPi / 2}) {
          int g = d == m::D_GGX ? m::G_SMITH_GGX_CORRELATED : m::G_SMITH_BECKMANN_CORRELATED;
          double e = furnace(d, g, alpha_strength, mu, phi_v, 256);
          double error = std::abs(e - furnace(d, g, alpha_strength, mu, phi_v, 128));
          EXPECT_LE(e, 1 + error + 1e-4) << "d " << d << " mu " << mu << " phi " << phi_v;
          EXPECT_GT(e, 0.2);
          highest = std::max(highest, e);
        }
  std::printf("anisotropic white furnace: highest E %.6f\n", highest);
}

}  // namespace
}  // namespace facet::materials

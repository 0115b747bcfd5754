// Directional albedo: the quadrature itself, the white furnace, Lambert.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "materials/albedo.h"
#include "materials/models.h"

namespace facet::materials {
namespace {

rules::f64::BrdfParams bare(int d, int g, double alpha) {
  rules::f64::BrdfParams p{};
  p.d_model = d;
  p.g_model = g;
  p.f_model = rules::f64::F_NONE;
  p.alpha = alpha;
  p.f0 = p.eta = p.k = p.diffuse = glm::dvec3(0);
  return p;
}

TEST(Albedo, GaussLegendreIsExactForPolynomials) {
  // An n-point rule integrates degree 2n - 1 exactly: x^k over [0, 1] is 1/(k+1).
  for (int n : {1, 2, 5, 16}) {
    QuadratureRule rule = gaussLegendre01(n);
    for (int k = 0; k < 2 * n; ++k) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], k);
      EXPECT_NEAR(sum, 1.0 / (k + 1), 1e-14) << "n=" << n << " k=" << k;
    }
  }
}

TEST(Albedo, LambertIsExactlyItsColor) {
  // 1e-12: the cosine map makes the integrand constant.
  rules::f64::BrdfParams p = bare(rules::f64::D_GGX, rules::f64::G_SMITH_GGX, 0.5);
  p.diffuse = {0.25, 0.5, 1.0};
  for (double mu : {0.05, 0.5, 1.0}) {
    AlbedoResult r = directionalAlbedo(p, mu, 16);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.diffuse[i], p.diffuse[i], 1e-12) << "mu=" << mu;
  }
}

TEST(Albedo, UniformDistributionWithImplicitGIsOneQuarter) {
  // Blinn-Phong at alpha = 1 is D = 1/pi; with G = (n.l)(n.v) and F = 1,
  // f = 1/(4 pi) and E = 1/4 for every mu (less the horizon's 1e-8).
  rules::f64::BrdfParams p = bare(rules::f64::D_BLINN_PHONG, rules::f64::G_IMPLICIT, 1.0);
  for (double mu : {0.1, 0.5, 0.9, 1.0}) {
    AlbedoResult r = directionalAlbedo(p, mu, 64);
    EXPECT_NEAR(r.albedo.x, 0.25, 1e-6) << "mu=" << mu;
  }
}

TEST(Albedo, ErrorEstimateBoundsTheTrueError) {
  // The reported estimate |E(n) - E(n/2)| must cover the difference to a
  // 4x finer quadrature, for narrow and broad lobes and grazing views.
  for (double alpha : {0.05, 0.5, 1.0}) {
    for (double mu : {0.05, 0.5, 1.0}) {
      rules::f64::BrdfParams p = bare(rules::f64::D_GGX, rules::f64::G_SMITH_GGX_CORRELATED, alpha);
      AlbedoResult r = directionalAlbedo(p, mu, 64);
      AlbedoResult fine = directionalAlbedo(p, mu, 256);
      EXPECT_LE(std::abs(r.albedo.x - fine.albedo.x), r.error_estimate + 1e-12) << "alpha=" << alpha << " mu=" << mu;
    }
  }
}

// Smith masking derived for the Beckmann microsurface, paired with a D
// that has more grazing microfacets than Beckmann (GGX's long tail,
// Blinn-Phong at high alpha), undercounts masking and creates energy; see
// docs/shading.md. Every other pairing is a valid masking model.
bool consistentPairing(int d, int g) {
  bool beckmann_smith = g == rules::f64::G_SMITH_BECKMANN || g == rules::f64::G_SMITH_BECKMANN_CORRELATED;
  return !beckmann_smith || d == rules::f64::D_BECKMANN;
}

struct Furnace {
  double highest = 0;
  std::string where;     // alpha and mu of the highest E
  std::string exceeded;  // first case above 1 beyond the quadrature error
};

Furnace whiteFurnace(int d, int g) {
  Furnace result;
  for (double alpha : {0.0, 0.05, 0.1, 0.25, 0.5, 0.75, 1.0})
    for (double mu : {0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
      AlbedoResult r = directionalAlbedo(bare(d, g, alpha), mu, 48);
      EXPECT_GE(r.albedo.x, 0.0);
      std::string where = "alpha=" + std::to_string(alpha) + " mu=" + std::to_string(mu);
      if (r.albedo.x > result.highest) {
        result.highest = r.albedo.x;
        result.where = where;
      }
      // Margin: the quadrature's own error estimate plus 1e-9.
      if (r.albedo.x > 1 + r.error_estimate + 1e-9 && result.exceeded.empty()) result.exceeded = where;
    }
  return result;
}

TEST(Albedo, WhiteFurnaceNeverGainsEnergy) {
  // E(mu) <= 1 with F = 1 for every consistent D x G, alpha in [0, 1]
  // (0 included), mu from grazing to normal.
  for (const ModelName& d : kDistributions)
    for (const ModelName& g : kGeometryTerms) {
      if (!consistentPairing(d.id, g.id)) continue;
      Furnace furnace = whiteFurnace(d.id, g.id);
      EXPECT_EQ(furnace.exceeded, "") << d.name << "/" << g.name;
      std::printf("furnace %-11s %-26s max E = %.6f at %s\n", d.name.data(), g.name.data(), furnace.highest,
                  furnace.where.c_str());
    }
}

TEST(Albedo, BeckmannSmithOnOtherSurfacesGainsEnergy) {
  // The documented exception, held to the size the table in docs/shading.md
  // gives it, so that the table stays true: each pairing reaches E > 1.3.
  for (int d : {rules::f64::D_GGX, rules::f64::D_BLINN_PHONG})
    for (int g : {rules::f64::G_SMITH_BECKMANN, rules::f64::G_SMITH_BECKMANN_CORRELATED}) {
      Furnace furnace = whiteFurnace(d, g);
      EXPECT_GT(furnace.highest, 1.3) << modelName(kDistributions, d) << "/" << modelName(kGeometryTerms, g);
      std::printf("furnace %-11s %-26s max E = %.6f at %s\n", modelName(kDistributions, d).data(),
                  modelName(kGeometryTerms, g).data(), furnace.highest, furnace.where.c_str());
    }
}

}  // namespace
}  // namespace facet::materials

namespace facet::materials {
namespace {

TEST(Albedo, AnisotropicQuadratureMeetsTheIsotropicAtVanishingAnisotropy) {
  // The anisotropic lobe is integrated over its sampler's whole square, the
  // isotropic one by symmetric panels: at strength 1e-4 (alpha_t - alpha_b =
  // 1e-8) the two must agree within 3e-4: the square's quadrature crosses
  // the horizon's kink, which limits it to about 1e-4 (docs/shading.md).
  for (int d : {rules::f64::D_GGX, rules::f64::D_BECKMANN})
    for (double alpha : {0.1, 0.5})
      for (double mu : {0.2, 0.7, 1.0}) {
        rules::f64::BrdfParams p = bare(
            d, d == rules::f64::D_GGX ? rules::f64::G_SMITH_GGX_CORRELATED : rules::f64::G_SMITH_BECKMANN_CORRELATED,
            alpha);
        AlbedoResult isotropic = directionalAlbedo(p, mu, 128);
        p.anisotropy = 1e-4;
        p.tangent = {std::cos(0.3), std::sin(0.3), 0};
        AlbedoResult anisotropic = directionalAlbedo(p, mu, 128);
        EXPECT_NEAR(anisotropic.albedo.x, isotropic.albedo.x, 3e-4) << "d " << d << " alpha " << alpha << " mu " << mu;
        // A rougher tangent direction reflects less at normal view.
        p.anisotropy = 0.9;
        if (mu == 1.0) {
          EXPECT_LT(directionalAlbedo(p, mu, 128).albedo.x, isotropic.albedo.x);
        }
      }
}

}  // namespace
}  // namespace facet::materials

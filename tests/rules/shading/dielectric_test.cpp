// The rough dielectric interface (rules/shading/dielectric.h), its
// continuation (transmissive_continuation.h) and Beer-Lambert absorption
// (absorption.h): energy conservation of the smooth limit, total internal
// reflection, the BTDF's generalized reciprocity, the sampler against its
// density, and the thin wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "rules/rules.h"
#include "tests/support/shading_frame.h"

namespace facet {
namespace {

using facet::testing::kN;
namespace m = rules::f64;


glm::dvec3 viewAt(double cosTheta) { return {std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), 0.0, cosTheta}; }

// Calls sample(u, u_interface, share) at one jittered point u of each of
// strata x strata cells of the unit square, share = 1 / their number.
template <class Sample>
void stratified(int strata, unsigned seed, Sample sample) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double share = 1 / (double(strata) * strata);
  for (int i = 0; i < strata; ++i)
    for (int j = 0; j < strata; ++j) {
      const glm::dvec2 u((i + uniform(random)) / strata, (j + uniform(random)) / strata);
      sample(u, uniform(random), share);
    }
}

// Reflected and transmitted energy of the interface seen from v, over a
// stratified grid of samples; the transmitted weight times eta^2 turns the
// radiance BTDF back into energy.
struct Energy {
  double reflected = 0;
  double transmitted = 0;
  double transmittedFraction = 0;  // of the samples
};

Energy interfaceEnergy(double alpha, double eta, double transmission, bool thin, double cosTheta, int strata) {
  const glm::dvec3 v = viewAt(cosTheta);
  Energy e;
  stratified(strata, 7, [&](glm::dvec2 u, double uInterface, double share) {
    const m::DielectricSample s = m::sample_dielectric(alpha, eta, transmission, thin, kN, kN, v, u, uInterface);
    if (s.transmitted) {
      e.transmitted += s.weight * (thin ? 1.0 : eta * eta) * share;
      e.transmittedFraction += share;
    } else {
      e.reflected += s.weight * share;
    }
  });
  return e;
}

TEST(Dielectric, SmoothInterfaceReflectsFresnelAndTransmitsTheRest) {
  for (double eta : {1.5, 1.0 / 1.5, 2.42})
    for (double cosTheta : {1.0, 0.8, 0.5, 0.2, 0.05}) {
      const Energy e = interfaceEnergy(0.0, eta, 1.0, false, cosTheta, 400);
      const double fresnel = m::fresnel_dielectric(eta, cosTheta);
      std::printf("eta %.3f cos %.2f: R %.6f (F %.6f) T %.6f, R + T - 1 = %+.2e\n", eta, cosTheta, e.reflected, fresnel,
                  e.transmitted, e.reflected + e.transmitted - 1);
      EXPECT_NEAR(e.reflected + e.transmitted, 1.0, 1e-3) << eta << " " << cosTheta;
      EXPECT_NEAR(e.reflected, fresnel, 4e-3) << eta << " " << cosTheta;
    }
}

TEST(Dielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double eta = 1.0 / 1.5;  // from glass into air
  const double criticalCos = std::sqrt(1 - eta * eta);
  for (double cosTheta : {criticalCos - 0.05, 0.3, 0.1}) {
    EXPECT_EQ(m::fresnel_dielectric(eta, cosTheta), 1.0);
    EXPECT_EQ(m::refract_through(viewAt(cosTheta), kN, eta), glm::dvec3(0.0));
    const Energy e = interfaceEnergy(0.0, eta, 1.0, false, cosTheta, 100);
    // Only GGX's far tail of normals, even at the smooth limit, still transmits.
    EXPECT_LT(e.transmittedFraction, 1e-3) << cosTheta;
    EXPECT_LT(e.transmitted, 1e-4) << cosTheta;
    EXPECT_NEAR(e.reflected, 1.0, 1e-3);
  }
  const Energy below = interfaceEnergy(0.0, eta, 1.0, false, criticalCos + 0.05, 100);
  EXPECT_GT(below.transmittedFraction, 0.3);
}

TEST(Dielectric, RefractionFollowsSnell) {
  const glm::dvec3 v = viewAt(0.6);
  const glm::dvec3 l = m::refract_through(v, kN, 1.5);
  EXPECT_NEAR(glm::length(l), 1.0, 1e-14);
  EXPECT_NEAR(std::sqrt(1 - l.z * l.z) * 1.5, std::sqrt(1 - 0.36), 1e-14);  // eta sin_t = sin_i
  EXPECT_LT(l.z, 0.0);
  EXPECT_NEAR(glm::length(m::transmission_half_vector(kN, l, v, 1.5) - kN), 0.0, 1e-12);
}

TEST(Dielectric, BtdfObeysGeneralizedReciprocity) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int compared = 0;
  for (double alpha : {0.05, 0.3, 0.8})
    for (double eta : {1.5, 1.0 / 1.33})
      for (int i = 0; i < 2000; ++i) {
        glm::dvec3 v = glm::normalize(glm::dvec3(uniform(random), uniform(random), std::abs(uniform(random))));
        glm::dvec3 l = glm::normalize(glm::dvec3(uniform(random), uniform(random), -std::abs(uniform(random))));
        const double forward = m::dielectric_btdf(alpha, eta, kN, l, v);
        const double backward = m::dielectric_btdf(alpha, 1 / eta, -kN, v, l);
        if (forward == 0 && backward == 0) continue;
        ++compared;
        // f_t(l, v) / n_v^2 = f_t(v, l) / n_l^2 (Walter et al. 2007, eq. 22).
        ASSERT_NEAR(forward * eta * eta / backward, 1.0, 1e-8) << alpha << " " << eta;
      }
  EXPECT_GT(compared, 1500);  // random pairs often have no microfacet between them
}

// The sampler's histogram over the sphere against its density integrated
// over each bin (bins equal in cos theta and phi); the density integrates to
// the share of samples that land on a valid side, at most 1.
TEST(Dielectric, SampledDirectionsFollowTheirDensity) {
  const int rows = 48, columns = 48, sub = 6;
  for (double eta : {1.5, 1.0 / 1.5})
    for (double transmission : {1.0, 0.5}) {
      const double alpha = 0.3;
      const glm::dvec3 v = viewAt(0.7);
      std::vector<double> expected(rows * columns, 0.0), observed(rows * columns, 0.0);
      double pdfIntegral = 0;
      const double cell = (2.0 / (rows * sub)) * (2 * M_PI / (columns * sub));
      for (int r = 0; r < rows * sub; ++r)
        for (int c = 0; c < columns * sub; ++c) {
          const double z = -1 + (r + 0.5) * 2.0 / (rows * sub), phi = (c + 0.5) * 2 * M_PI / (columns * sub);
          const double s = std::sqrt(1 - z * z);
          const double p =
              m::dielectric_pdf(alpha, eta, transmission, kN, {s * std::cos(phi), s * std::sin(phi), z}, v);
          expected[(r / sub) * columns + c / sub] += p * cell;
          pdfIntegral += p * cell;
        }
      std::mt19937_64 random(11);
      std::uniform_real_distribution<double> uniform(0.0, 1.0);
      const int samples = 1000000;
      int valid = 0;
      for (int i = 0; i < samples; ++i) {
        const m::DielectricSample s = m::sample_dielectric(alpha, eta, transmission, false, kN, kN, v,
                                                           {uniform(random), uniform(random)}, uniform(random));
        if (s.weight <= 0) continue;
        ++valid;
        const glm::dvec3 l = s.direction;
        double phi = std::atan2(l.y, l.x);
        if (phi < 0) phi += 2 * M_PI;
        const int r = std::min(rows - 1, int((l.z + 1) / 2 * rows));
        const int c = std::min(columns - 1, int(phi / (2 * M_PI) * columns));
        observed[r * columns + c] += 1.0 / samples;
      }
      double variation = 0;
      for (int b = 0; b < rows * columns; ++b) variation += std::abs(observed[b] - expected[b]);
      std::printf("eta %.3f transmission %.1f: integral of pdf %.5f, valid samples %.5f, total variation %.4f\n", eta,
                  transmission, pdfIntegral, double(valid) / samples, variation);
      EXPECT_LE(pdfIntegral, 1.0 + 2e-3);
      EXPECT_NEAR(pdfIntegral, double(valid) / samples, 5e-3);
      EXPECT_LT(variation, 0.02);
    }
}

// A rough interface loses what single scattering misses and no more: the
// sampler's reflected and transmitted energy is the glass albedo the
// compensation tables hold (glass_albedo_entry), which is 1 in the smooth
// limit; with 1 / E on the dielectric lobes, the material's continuation
// keeps all it receives (docs/shading.md, "Energy compensation of glass").
TEST(Dielectric, RoughInterfaceLosesOnlyWhatSingleScatteringMissesAndCompensationReturnsIt) {
  for (const bool thin : {false, true})
    for (const double eta : {1.5, 1.0 / 1.5})
      for (const double cosTheta : {0.3, 0.7, 1.0}) {
        EXPECT_NEAR(m::glass_albedo_entry(cosTheta, 0.0, eta, thin, 1024).x, 1.0, 2e-4);
        for (const double alpha : {0.1, 0.5}) {
          const Energy e = interfaceEnergy(alpha, eta, 1.0, thin, cosTheta, 300);
          const double albedo = m::glass_albedo_entry(cosTheta, alpha, eta, thin, 16384).x;
          m::BrdfParams p{};
          p.d_model = m::D_GGX;
          p.g_model = m::G_SMITH_GGX_CORRELATED;
          p.alpha = alpha;
          p.f0 = p.k = p.diffuse = glm::dvec3(0.0);
          const m::TransmissionParams t{1.0, eta, thin, glm::dvec3(0.0), 0.0};
          p = m::transmissive_brdf_params(p, t, true, glm::dvec3(1.0), 0.0);
          double kept = 0;
          stratified(300, 9, [&](glm::dvec2 u, double uInterface, double share) {
            const m::TransmissiveContinuation c =
                m::continue_path_transmissive(p, t, kN, kN, viewAt(cosTheta), glm::dvec3(1 / albedo), u, uInterface);
            kept += c.weight.x * (c.transmitted && !thin ? eta * eta : 1.0) * share;
          });
          std::printf("alpha %.1f eta %.3f%s cos %.1f: R + T = %.5f, albedo %.5f, compensated %.5f\n", alpha, eta,
                      thin ? " thin" : "", cosTheta, e.reflected + e.transmitted, albedo, kept);
          EXPECT_NEAR(e.reflected + e.transmitted, albedo, 2e-3);
          EXPECT_LT(albedo, alpha < 0.2 ? 1.0 : 0.98);
          EXPECT_NEAR(kept, 1.0, 2e-3);
        }
      }
}

TEST(Dielectric, ThinWallTransmitsStraightThrough) {
  const double eta = 1.5, f = m::fresnel_dielectric(eta, 1.0);
  const Energy e = interfaceEnergy(0.0, eta, 1.0, true, 1.0, 400);
  EXPECT_NEAR(e.reflected, f, 2e-3);
  EXPECT_NEAR(e.reflected + e.transmitted, 1.0, 1e-3);
  const m::DielectricSample s = m::sample_dielectric(0.0, eta, 1.0, true, kN, kN, viewAt(0.6), {0.3, 0.6}, 0.99);
  ASSERT_TRUE(s.transmitted);
  EXPECT_NEAR(glm::length(s.direction + viewAt(0.6)), 0.0, 1e-2);  // not bent, within the smooth limit's blur
  EXPECT_NEAR(s.cos_inside, std::sqrt(1 - 0.64 / (eta * eta)), 1e-2);
}

TEST(Absorption, BeerLambertGivesTheAttenuationColourAtItsDistance) {
  const glm::dvec3 color(0.9, 0.5, 0.1);
  const glm::dvec3 sigma = m::absorption_coefficient(color, 2.0);
  const glm::dvec3 at = m::beer_lambert(sigma, 2.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(at[i], color[i], 1e-15);
  EXPECT_NEAR(m::beer_lambert(sigma, 4.0).y, 0.25, 1e-15);
  const glm::dvec3 none = m::absorption_coefficient(color, m::INFINITE_DISTANCE);
  EXPECT_EQ(none, glm::dvec3(0.0));
  EXPECT_EQ(m::beer_lambert(none, m::INFINITE_DISTANCE), glm::dvec3(1.0));
  EXPECT_EQ(m::beer_lambert(m::absorption_coefficient(glm::dvec3(1.0), 1.0), 5.0), glm::dvec3(1.0));
}

// The whole material: diffuse mixed in adds its albedo to the reflection
// side and leaves the transmission side as the dielectric alone gives it.
TEST(TransmissiveContinuation, DiffuseLobeAddsItsAlbedoOnTheReflectionSide) {
  m::BrdfParams p{};
  p.d_model = m::D_GGX;
  p.g_model = m::G_SMITH_GGX_CORRELATED;
  p.f_model = m::F_DIELECTRIC;
  p.alpha = 0.2;
  p.f0 = p.k = glm::dvec3(0.0);
  p.eta = glm::dvec3(1.5);
  p.diffuse = glm::dvec3(0.6);
  m::TransmissionParams t{0.5, 1.5, false, glm::dvec3(0.0), 0.0};
  p = m::transmissive_brdf_params(p, t, true, glm::dvec3(1.0), 0.0);
  EXPECT_EQ(p.diffuse, glm::dvec3(0.3));
  const glm::dvec3 v = viewAt(0.8);
  double reflected = 0, transmitted = 0;
  stratified(700, 5, [&](glm::dvec2 u, double uInterface, double share) {
    const m::TransmissiveContinuation c =
        m::continue_path_transmissive(p, t, kN, kN, v, glm::dvec3(1.0), u, uInterface);
    (c.transmitted ? transmitted : reflected) += c.weight.x * share;
  });
  const Energy dielectric = interfaceEnergy(0.2, 1.5, 0.5, false, 0.8, 700);
  std::printf("mixed: reflected %.5f (dielectric %.5f + diffuse 0.3), transmitted x eta^2 %.5f (dielectric %.5f)\n",
              reflected, dielectric.reflected, transmitted * 2.25, dielectric.transmitted);
  EXPECT_NEAR(reflected, dielectric.reflected + 0.3, 5e-3);
  EXPECT_NEAR(transmitted * 2.25, dielectric.transmitted, 5e-3);
}

// glTF's mix(dielectric, metal, metallic) over a transmissive material
// (KHR_materials_transmission): each colour channel transmits (1 - metallic)
// base of what the bare dielectric transmits, and a material all metal
// reflects what the opaque metal of F(0) = base reflects, transmitting none.
TEST(TransmissiveContinuation, TheBaseColourTintsTheTransmissionAndAMetalsShareStaysOpaque) {
  const glm::dvec3 base(0.2, 0.5, 0.9);
  const glm::dvec3 v = viewAt(0.8);
  m::TransmissionParams t{1.0, 1.5, false, glm::dvec3(0.0), 0.0};
  const auto integrate = [&](double metallic, bool transmissive) {
    m::BrdfParams p{};
    p.d_model = m::D_GGX;
    p.g_model = m::G_SMITH_GGX_CORRELATED;
    p.f_model = m::F_SCHLICK;
    p.alpha = 0.2;
    p.f0 = base;
    p.eta = glm::dvec3(1.5);
    p.diffuse = base * (1 - metallic);
    if (transmissive) p = m::transmissive_brdf_params(p, t, true, base, metallic);
    std::vector<Energy> e(3);
    stratified(600, 11, [&](glm::dvec2 u, double uInterface, double share) {
      glm::dvec3 weight;
      bool transmitted = false;
      if (transmissive) {
        const m::TransmissiveContinuation c =
            m::continue_path_transmissive(p, t, kN, kN, v, glm::dvec3(1.0), u, uInterface);
        weight = c.weight, transmitted = c.transmitted;
      } else {
        weight = m::continue_path(p, kN, kN, v, glm::dvec3(1.0), u).weight;
      }
      for (int c = 0; c < 3; ++c) {
        Energy& channel = e[std::size_t(c)];
        (transmitted ? channel.transmitted : channel.reflected) += weight[c] * share;
      }
    });
    return e;
  };
  const Energy dielectric = interfaceEnergy(0.2, 1.5, 1.0, false, 0.8, 600);
  const std::vector<Energy> half = integrate(0.5, true);
  const std::vector<Energy> metal = integrate(1.0, true), opaque = integrate(1.0, false);
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: transmitted x eta^2 %.5f (expected %.5f); all metal reflects %.5f, opaque metal %.5f\n", c,
                half[std::size_t(c)].transmitted * 2.25, 0.5 * base[c] * dielectric.transmitted,
                metal[std::size_t(c)].reflected, opaque[std::size_t(c)].reflected);
    EXPECT_NEAR(half[std::size_t(c)].transmitted * 2.25, 0.5 * base[c] * dielectric.transmitted, 5e-3) << c;
    EXPECT_EQ(metal[std::size_t(c)].transmitted, 0.0) << c;
    EXPECT_NEAR(metal[std::size_t(c)].reflected, opaque[std::size_t(c)].reflected, 5e-3) << c;
  }
}

}  // namespace
}  // namespace facet

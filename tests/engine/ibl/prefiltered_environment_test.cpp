// The CPU reference of the split sum's precomputation against what each
// piece must equal: constants stay constant, SH irradiance and the
// prefiltered levels against brute-force integrals over the map's texels,
// the DFG tables against the directional albedo of materials/albedo.h, and
// the compensated white furnace they give.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "rules/rules.h"
#include "engine/ibl/prefiltered_environment.h"
#include "materials/albedo.h"
#include "scenes/environment_map.h"
#include "tests/support/compensated_furnace.h"
#include "tests/support/environment_maps.h"

namespace facet::ibl {
namespace {

namespace m = rules::f64;
using testing::integrateOverTexels;
using testing::mapOf;
using testing::maxRelativeDifference;
using testing::skyWithSun;

const glm::dvec3 kNormals[] = {{0, 1, 0},         {0, -1, 0},       {1, 0, 0},       {0, 0, -1},
                               {0.6, 0.5, -0.62}, {-0.3, 0.2, 0.9}, {0.5, -0.7, 0.1}};

PrefilterSettings smallSettings() {
  PrefilterSettings s;
  s.firstLevelWidth = 32;
  s.samples = 64;
  s.dfgSize = 8;
  s.dfgSamples = 64;
  return s;
}

TEST(PrefilteredEnvironment, LevelsFollowTheLadder) {
  const auto map = mapOf(64, 32, [](glm::dvec3) { return glm::dvec3(1.0); });
  PrefilterSettings settings = smallSettings();
  settings.firstLevelWidth = 64;
  const PrefilteredEnvironment env = prefilterOnCpu(map, {}, settings);
  ASSERT_EQ(env.levels.size(), 6u);
  const int widths[] = {64, 64, 32, 16, 16, 16};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(env.levels[i].width, widths[i]) << "level " << i;
    EXPECT_EQ(env.levels[i].height, widths[i] / 2) << "level " << i;
    EXPECT_DOUBLE_EQ(env.levels[i].alpha, m::sqr(i / 5.0)) << "level " << i;
    EXPECT_EQ(env.levels[i].rgb.size(), std::size_t(3 * widths[i] * widths[i] / 2));
  }
  EXPECT_TRUE(env.dfg.empty());
}

TEST(PrefilteredEnvironment, ConstantMapStaysConstant) {
  const glm::dvec3 color(0.3, 1.5, 2.0);
  const auto map = mapOf(64, 32, [&](glm::dvec3) { return color; });
  const glm::dvec3 stored(map.texel(0, 0));
  const PrefilteredEnvironment env = prefilterOnCpu(map, {{m::D_GGX, m::G_SMITH_GGX_CORRELATED}}, smallSettings());
  for (const RadianceLevel& level : env.levels)
    for (std::size_t i = 0; i < level.rgb.size(); ++i)
      ASSERT_NEAR(level.rgb[i], stored[i % 3], 1e-6 * stored[i % 3]) << "alpha " << level.alpha << " float " << i;
  for (const glm::dvec3& n : kNormals) {
    EXPECT_LT(maxRelativeDifference(irradianceOverPi(env, n), stored), 1e-12);
    for (double alpha : {0.0, 0.1, 0.5, 1.0})
      EXPECT_LT(maxRelativeDifference(prefilteredRadiance(env, n, alpha), stored), 1e-6);
  }
}

// Brute force: E(n) / pi = (1 / pi) integral of L max(0, n.l) over the
// map's texels, each split into 8 x 8 cells.
glm::dvec3 bruteForceIrradianceOverPi(const scene::EnvironmentMap& map, const glm::dvec3& n) {
  return integrateOverTexels(map, 8, [&](glm::dvec3 l) { return std::max(0.0, glm::dot(n, l)); }) / m::PI;
}

// Bands 0-2 hold a map quadratic in the direction exactly; what is left is
// the piecewise-constant texels' own high-band content.
TEST(PrefilteredEnvironment, ShIrradianceOfALowFrequencyMapMatchesBruteForce) {
  const auto map = mapOf(64, 32, [](glm::dvec3 d) {
    return glm::dvec3(1 + d.y + 0.5 * d.x * d.z, 1 + 0.5 * d.x + 0.3 * d.y * d.y,
                      1 - 0.3 * d.z + 0.4 * (d.x * d.x - d.y * d.z));
  });
  const PrefilteredEnvironment env = prefilterOnCpu(map, {}, smallSettings());
  for (const glm::dvec3& direction : kNormals) {
    const glm::dvec3 n = glm::normalize(direction);
    EXPECT_LT(maxRelativeDifference(irradianceOverPi(env, n), bruteForceIrradianceOverPi(map, n)), 1e-4)
        << n.x << " " << n.y << " " << n.z;
  }
}

// Worst |irradiance - brute force| over kNormals, relative to the mean irradiance.
double worstIrradianceError(const PrefilteredEnvironment& env, const scene::EnvironmentMap& map) {
  const glm::dvec3 mean = env.irradianceSh[0] * m::sh_basis(0, glm::dvec3(0.0));
  double worst = 0;
  for (const glm::dvec3& direction : kNormals) {
    const glm::dvec3 n = glm::normalize(direction);
    const glm::dvec3 difference = irradianceOverPi(env, n) - bruteForceIrradianceOverPi(map, n);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(difference[c]) / mean[c]);
  }
  return worst;
}

// With a sun 100 times the sky, bands 0-2 miss the sharp part of the cosine
// lobe's response; the convolved map holds it, and the rule takes the map.
TEST(PrefilteredEnvironment, UnderASunTheRuleTakesTheIrradianceMap) {
  const auto map = mapOf(64, 32, skyWithSun);
  PrefilteredEnvironment env = prefilterOnCpu(map, {}, smallSettings());
  EXPECT_TRUE(env.irradianceFromMap);
  const double fromMap = worstIrradianceError(env, map);
  env.irradianceFromMap = false;
  const double fromSh = worstIrradianceError(env, map);
  std::printf("sky + sun: SH misses the map by %.3g; worst |difference| / mean vs brute force: map %.3g, SH %.3g\n",
              shIrradianceError(env.irradianceSh, env.irradianceMap), fromMap, fromSh);
  EXPECT_GT(shIrradianceError(env.irradianceSh, env.irradianceMap), 0.01);
  EXPECT_LT(fromMap, 0.01);
  EXPECT_LT(fromSh, 0.1);
}

// A normal at a pole has no azimuth, and the GPU's float normal of a floor
// is (1e-8, 1, -1e-8) where the CPU's is (0, 1, 0): normals within 1e-7 of
// a pole read the same irradiance whatever their azimuth, and a degree away
// the map still holds the brute-force irradiance.
TEST(PrefilteredEnvironment, TheIrradianceMapAtAPoleIsOneValueWhateverTheAzimuth) {
  const auto map = mapOf(64, 32, skyWithSun);
  const PrefilteredEnvironment env = prefilterOnCpu(map, {}, smallSettings());
  ASSERT_TRUE(env.irradianceFromMap);
  for (double pole : {1.0, -1.0}) {
    const glm::dvec3 atPole = irradianceOverPi(env, glm::dvec3(0, pole, 0));
    for (double azimuth = 0; azimuth < 2 * m::PI; azimuth += 0.7) {
      const glm::dvec3 near = glm::normalize(glm::dvec3(1e-7 * std::cos(azimuth), pole, 1e-7 * std::sin(azimuth)));
      EXPECT_LT(maxRelativeDifference(irradianceOverPi(env, near), atPole), 1e-6)
          << "pole " << pole << " azimuth " << azimuth;
      const glm::dvec3 degree = glm::normalize(glm::dvec3(0.017 * std::cos(azimuth), pole, 0.017 * std::sin(azimuth)));
      EXPECT_LT(maxRelativeDifference(irradianceOverPi(env, degree), bruteForceIrradianceOverPi(map, degree)), 0.01)
          << "pole " << pole << " azimuth " << azimuth;
    }
  }
}

// A map quadratic in the direction is all bands 0-2: the SH is exact, and
// the rule keeps it.
TEST(PrefilteredEnvironment, ForASoftMapTheRuleKeepsTheSh) {
  const auto map =
      mapOf(64, 32, [](glm::dvec3 d) { return glm::dvec3(1.2 + d.y, 1 + 0.5 * d.x, 1 - 0.3 * d.z * d.x); });
  const PrefilteredEnvironment env = prefilterOnCpu(map, {}, smallSettings());
  std::printf("soft map: SH misses the map by %.3g\n", shIrradianceError(env.irradianceSh, env.irradianceMap));
  EXPECT_FALSE(env.irradianceFromMap);
}

// The shipped maps both hold more than bands 0-2 carry: the sunrise's sun,
// the courtyard's bright sky against a dark ground.
TEST(PrefilteredEnvironment, TheShippedMapsTakeTheIrradianceMap) {
  PrefilterSettings settings = smallSettings();
  settings.levels = 1;
  for (const char* file : {"sunrise.exr", "courtyard_256x128.hdr"}) {
    const scene::EnvironmentMap map = scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / file);
    const PrefilteredEnvironment env = prefilterOnCpu(map, {}, settings);
    std::printf("%s: SH misses the map by %.3g\n", file, shIrradianceError(env.irradianceSh, env.irradianceMap));
    EXPECT_TRUE(env.irradianceFromMap) << file;
  }
}

// The map is the cosine-weighted mean over its source's texels: a constant
// map's irradiance is the constant, to float's rounding.
TEST(PrefilteredEnvironment, IrradianceMapOfAConstantMapIsExact) {
  const glm::dvec3 color(0.3, 1.5, 2.0);
  const auto map = mapOf(256, 128, [&](glm::dvec3) { return color; });
  PrefilteredEnvironment env = prefilterOnCpu(map, {}, smallSettings());
  EXPECT_EQ(env.irradianceMap.width, 64);
  EXPECT_EQ(env.irradianceMap.height, 33) << "rows from pole to pole";
  env.irradianceFromMap = true;
  const glm::dvec3 stored(map.texel(0, 0));
  for (const glm::dvec3& n : kNormals)
    EXPECT_LT(maxRelativeDifference(irradianceOverPi(env, glm::normalize(n)), stored), 1e-6);
}

// Worst relative difference, over a few texels of the level filtered at
// alpha = 1, from the expectation filtered importance sampling estimates:
// the specular lobe of n = v = r over l, integral of L D(h) G(l, r) over
// integral of D(h) G(l, r), h = (l + r) / |l + r| (prefilter_sample_weight).
double roughestLevelError(const scene::EnvironmentMap& map, int samples) {
  PrefilterSettings settings = smallSettings();
  settings.levels = 2;
  settings.samples = samples;
  const PrefilteredEnvironment env = prefilterOnCpu(map, {}, settings);
  const RadianceLevel& roughest = env.levels[1];
  EXPECT_EQ(roughest.alpha, 1.0);
  double worst = 0;
  for (const auto& [x, y] : {std::pair{3, 2}, {10, 5}, {17, 8}, {25, 11}, {30, 15}, {6, 13}}) {
    const glm::dvec3 r = m::environment_direction(glm::dvec2((x + 0.5) / roughest.width, (y + 0.5) / roughest.height));
    double weight = 0;
    const glm::dvec3 convolved = integrateOverTexels(
        map, 4,
        [&](glm::dvec3 l) {
          const double nl = glm::dot(r, l);
          if (nl <= 0) return 0.0;
          const glm::dvec3 h = glm::normalize(l + r);
          const double rh = glm::dot(r, h);
          return m::microfacet_D(m::D_GGX, 1.0, rh, m::sin2_between(r, h)) *
                 m::microfacet_G(m::G_SMITH_GGX_CORRELATED, 1.0, nl, 1.0, rh, rh);
        },
        &weight);
    const float* texel = &roughest.rgb[3 * (y * roughest.width + x)];
    worst = std::max(worst, maxRelativeDifference(glm::dvec3(texel[0], texel[1], texel[2]), convolved / weight));
  }
  return worst;
}

// The mip chain's blur is filtered importance sampling's bias: it shrinks as
// the samples grow (measured on this map: 2.2% at 1024 samples, 0.43% at
// 4096; with the sun 10% and 4%).
TEST(PrefilteredEnvironment, RoughestLevelMatchesBruteForceGgxConvolution) {
  const auto sky = mapOf(
      64, 32, [](glm::dvec3 d) { return glm::dvec3(0.4, 0.6, 1.0) * (1.2 + d.y) + glm::dvec3(0.2, 0.1, 0.0) * d.x; });
  const double skyError = roughestLevelError(sky, 4096);
  const double sunError = roughestLevelError(mapOf(64, 32, skyWithSun), 4096);
  std::printf("alpha = 1 level vs brute-force GGX convolution, 4096 samples: sky %.3g, sky + sun %.3g\n", skyError,
              sunError);
  EXPECT_LT(skyError, 0.006);
  EXPECT_LT(sunError, 0.05);
}

struct DfgError {
  double grazing = 0;  // n.v < minNv
  double rest = 0;
  double restNv = 0;
  double restRoughness = 0;
};

// |F0 scale + bias - E| with F = 1 against the directional albedo, at points
// between the table's entries (dfgLookup's bilinear interpolation included),
// up to its last column's n.v: beyond it the lookup clamps.
DfgError dfgError(const DfgTable& table, double minNv) {
  DfgError e;
  for (double nv = 0.0113; nv < 0.99; nv += 0.0617)
    for (double roughness = 0.013; roughness < 1; roughness += 0.0571) {
      const m::BrdfParams params{table.distribution, table.geometry,  m::F_SCHLICK,    roughness * roughness,
                                 glm::dvec3(1.0),    glm::dvec3(1.0), glm::dvec3(0.0), 0.0,
                                 glm::dvec3(0.0)};
      const double albedo = materials::directionalAlbedo(params, nv, 128).specular.x;
      const glm::dvec2 scaleBias = dfgLookup(table, nv, roughness * roughness);
      const double error = std::abs(scaleBias.x + scaleBias.y - albedo);
      if (nv < minNv) {
        e.grazing = std::max(e.grazing, error);
      } else if (error > e.rest) {
        e.rest = error, e.restNv = nv, e.restRoughness = roughness;
      }
    }
  std::printf(
      "D %d G %d: worst |scale + bias - E| = %.3g for n.v >= %.2f (at n.v %.3f, sqrt(alpha) %.3f), %.3g below\n",
      table.distribution, table.geometry, e.rest, minNv, e.restNv, e.restRoughness, e.grazing);
  return e;
}

// At 1024 samples per entry the Hammersley points' own error (about 1/n)
// dominates: 1.4e-3 at worst above n.v = 0.2. Towards grazing E falls
// faster than the table's first column (n.v = 1/64) follows: up to 3.7e-2.
TEST(PrefilteredEnvironment, DfgMatchesDirectionalAlbedo) {
  const ModelPairs pairs = {
      {m::D_GGX, m::G_SMITH_GGX}, {m::D_BECKMANN, m::G_SMITH_BECKMANN_CORRELATED}, {m::D_BLINN_PHONG, m::G_KELEMEN}};
  PrefilterSettings settings;
  settings.levels = 1;
  settings.dfgSamples = 1024;
  const PrefilteredEnvironment env = prefilterOnCpu(mapOf(16, 8, skyWithSun), pairs, settings);
  ASSERT_EQ(env.dfg.size(), pairs.size());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    EXPECT_EQ(env.dfg[p].distribution, pairs[p].first);
    EXPECT_EQ(env.dfg[p].geometry, pairs[p].second);
    EXPECT_EQ(env.dfg[p].size, settings.dfgSize);
    const DfgError e = dfgError(env.dfg[p], 0.2);
    EXPECT_LT(e.rest, 2e-3);
    EXPECT_LT(e.grazing, 4e-2);
  }
}

// At the default 4096 samples per entry the table holds E within 1e-3 from
// n.v = 0.1, and scales the lobe for multiple scattering: with F = 1 the
// compensated white furnace reflects everything, within 1% from n.v = 0.1.
TEST(PrefilteredEnvironment, DfgAtTheDefaultSamplesMatchesDirectionalAlbedoAndCompensatesTheFurnace) {
  PrefilterSettings settings;
  settings.levels = 1;
  const PrefilteredEnvironment env =
      prefilterOnCpu(mapOf(16, 8, skyWithSun), {{m::D_GGX, m::G_SMITH_GGX_CORRELATED}}, settings);
  const DfgError e = dfgError(env.dfg[0], 0.1);
  EXPECT_LT(e.rest, 1e-3);
  EXPECT_LT(e.grazing, 4e-2);
  EXPECT_LT(testing::compensatedFurnaceError(env.dfg[0], 0.1), 1e-2);
}

// The factor read without the table equals the table's, to its float
// storage: F0 = 1 gives 1 / E, F0 = 0 leaves the lobe as it is, F0 between
// scales the missing energy.
TEST(PrefilteredEnvironment, EnergyCompensationOnDemandMatchesTheTable) {
  PrefilterSettings settings;
  settings.levels = 1;
  settings.dfgSize = 8;
  settings.dfgSamples = 64;
  const PrefilteredEnvironment env =
      prefilterOnCpu(mapOf(16, 8, skyWithSun), {{m::D_GGX, m::G_SMITH_GGX_CORRELATED}}, settings);
  for (const double nv : {0.07, 0.33, 0.8, 1.0})
    for (const double alpha : {0.0, 0.11, 0.5, 1.0}) {
      const glm::dvec2 table = dfgLookup(env.dfg[0], nv, alpha);
      const glm::dvec2 onDemand = dfgLookupOnDemand(m::D_GGX, m::G_SMITH_GGX_CORRELATED, nv, alpha, settings);
      EXPECT_LT(testing::maxRelativeDifference(glm::dvec3(onDemand, 0.0), glm::dvec3(table, 0.0)), 1e-7);
      m::BrdfParams params{
          m::D_GGX,        m::G_SMITH_GGX_CORRELATED, m::F_SCHLICK, alpha,          glm::dvec3(1.0, 0.0, 0.5),
          glm::dvec3(1.0), glm::dvec3(0.0),           0.0,          glm::dvec3(0.0)};
      const glm::dvec3 factor = energyCompensationOnDemand(params, nv, settings);
      EXPECT_NEAR(factor.x, 1 / (table.x + table.y), 1e-6) << nv << " " << alpha;
      EXPECT_EQ(factor.y, 1.0);
      EXPECT_NEAR(factor.z, 1 + m::fresnel_F(params, 1.0).z * (1 / (table.x + table.y) - 1), 1e-6);
    }
}

}  // namespace
}  // namespace facet::ibl

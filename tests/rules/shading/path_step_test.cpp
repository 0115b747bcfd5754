// One step of a path (rules/shading/path_step.h), the one order both
// backends take: roulette keeps the mean, a lobe kind over its limit ends
// the path, a black vertex ends it, a ray leaves on the side it goes to, and
// the medium changes only through a solid's interface.
#include <gtest/gtest.h>

#include <cstdint>

#include "rules/rules.h"
#include "tests/support/shading_frame.h"

namespace facet::rules {
namespace {

using facet::testing::kN;
namespace m = f64;
constexpr double kOffset = 1e-3;
const glm::ivec3 kNoLimits(-1);

m::PathVertex lambert(double albedo) {
  m::PathVertex x{};
  x.position = {1, 2, 3};
  x.n = x.ng = kN;
  x.v = glm::normalize(glm::dvec3(0.3, 0.1, 1));
  x.params.d_model = m::D_GGX;
  x.params.g_model = m::G_SMITH_GGX_CORRELATED;
  x.params.f_model = m::F_DIELECTRIC;  // of index 1: no interface, Lambert alone
  x.params.alpha = 0.25;
  x.params.eta = glm::dvec3(1.0);
  x.params.diffuse = glm::dvec3(albedo);
  x.specular_scale = glm::dvec3(1.0);
  x.outside = true;
  return x;
}

m::PathVertex glass(bool outside) {
  m::PathVertex x = lambert(0.0);
  x.params.f_model = m::F_DIELECTRIC;
  x.params.eta = glm::dvec3(1.5);
  x.params.alpha = 0.01;
  x.transmissive = true;
  x.transmission = {1.0, 1.5, false, glm::dvec3(0.5, 1.0, 2.0), 0.0};
  x.outside = outside;
  x.params = m::transmissive_brdf_params(x.params, x.transmission, outside, glm::dvec3(1.0), 0.0);
  return x;
}

m::PathCarry fresh() { return {glm::dvec3(1.0), glm::dvec3(0.0), glm::uvec3(0)}; }

m::PathSampleKey key(std::uint32_t sample) { return {17, sample, 4096, 5}; }

TEST(PathStep, AContinuationLeavesAboveTheSurfaceWeightedByTheAlbedo) {
  int continued = 0;
  for (std::uint32_t sample = 0; sample < 256; ++sample) {
    const m::PathStep step = m::path_step(lambert(0.5), fresh(), key(sample), 1, false, kNoLimits, kOffset);
    if (!step.continues) continue;
    ++continued;
    EXPECT_GT(glm::dot(step.direction, kN), 0.0);
    EXPECT_EQ(step.origin, lambert(0.5).position + kOffset * kN);
    EXPECT_EQ(step.t_min, kOffset);
    EXPECT_EQ(step.crossing.back, 0.0);               // an opaque surface is left by the offset alone
    EXPECT_NEAR(step.carry.throughput.x, 0.5, 1e-9);  // f cos / pdf of a cosine-sampled Lambert lobe
    EXPECT_EQ(step.carry.taken, glm::uvec3(0));      // nothing counted without limits
  }
  EXPECT_EQ(continued, 256);  // vertex 1 plays no roulette with a throughput of 1
}

TEST(PathStep, ABlackVertexEndsThePath) {
  for (std::uint32_t sample = 0; sample < 64; ++sample)
    EXPECT_FALSE(m::path_step(lambert(0.0), fresh(), key(sample), 1, false, kNoLimits, kOffset).continues);
}

TEST(PathStep, ALobeKindOverItsLimitEndsThePathAndOthersAreCounted) {
  const glm::ivec3 noDiffuse(0, -1, -1), oneDiffuse(1, -1, -1);
  for (std::uint32_t sample = 0; sample < 64; ++sample) {
    EXPECT_FALSE(m::path_step(lambert(0.5), fresh(), key(sample), 1, true, noDiffuse, kOffset).continues);
    const m::PathStep step = m::path_step(lambert(0.5), fresh(), key(sample), 1, true, oneDiffuse, kOffset);
    ASSERT_TRUE(step.continues);
    EXPECT_EQ(step.carry.taken, glm::uvec3(1, 0, 0));
    m::PathCarry second = step.carry;
    EXPECT_FALSE(m::path_step(lambert(0.5), second, key(sample), 2, true, oneDiffuse, kOffset).continues);
  }
}

TEST(PathStep, RouletteKeepsTheMeanOfTheThroughput) {
  m::PathCarry dim = fresh();
  dim.throughput = glm::dvec3(0.05);
  const std::uint32_t vertex = 8;
  ASSERT_LT(m::path_survival_probability(dim.throughput, vertex), 1.0);
  double sum = 0;
  const int samples = 20000;
  for (int sample = 0; sample < samples; ++sample) {
    const m::PathStep step =
        m::path_step(lambert(0.5), dim, key(std::uint32_t(sample)), vertex, false, kNoLimits, kOffset);
    if (step.continues) sum += step.carry.throughput.x;
  }
  EXPECT_NEAR(sum / samples, 0.05 * 0.5, 0.05 * 0.5 * 0.05);
}

TEST(PathStep, ThroughASolidTheMediumIsTheInsideOnlyBetweenItsInterfaces) {
  int entered = 0, left = 0;
  for (std::uint32_t sample = 0; sample < 256; ++sample) {
    const m::PathStep in = m::path_step(glass(true), fresh(), key(sample), 1, false, kNoLimits, kOffset);
    if (in.continues && in.transmitted) {
      ++entered;
      EXPECT_EQ(in.carry.sigma, glass(true).transmission.sigma);
      EXPECT_LT(glm::dot(in.direction, kN), 0.0);
      // From the vertex, backed up to one offset above the surface it went
      // through, t from 0, keeping the far side however near.
      EXPECT_EQ(in.t_min, 0.0);
      EXPECT_TRUE(in.crossing.inside);
      EXPECT_NEAR(glm::dot(in.origin - glass(true).position, kN), kOffset, 1e-12);
    } else if (in.continues) {
      EXPECT_EQ(in.carry.sigma, glm::dvec3(0.0));
      EXPECT_FALSE(in.crossing.inside);  // reflected outside: into air
    }
    m::PathCarry inside = fresh();
    inside.sigma = glass(true).transmission.sigma;
    const m::PathStep out = m::path_step(glass(false), inside, key(sample), 2, false, kNoLimits, kOffset);
    if (out.continues && out.transmitted) {
      ++left;
      EXPECT_EQ(out.carry.sigma, glm::dvec3(0.0));
      EXPECT_FALSE(out.crossing.inside);
    } else if (out.continues) {
      EXPECT_EQ(out.carry.sigma, inside.sigma);  // reflected inside: still in the medium
      EXPECT_TRUE(out.crossing.inside);
    }
  }
  EXPECT_GT(entered, 128);
  EXPECT_GT(left, 0);
}

TEST(PathStep, AThinWallKeepsTheMediumItWasIn) {
  m::PathVertex wall = glass(true);
  wall.transmission.thin_walled = true;
  int through = 0;
  for (std::uint32_t sample = 0; sample < 128; ++sample) {
    const m::PathStep step = m::path_step(wall, fresh(), key(sample), 1, false, kNoLimits, kOffset);
    if (!step.continues || !step.transmitted) continue;
    ++through;
    EXPECT_EQ(step.carry.sigma, glm::dvec3(0.0));
  }
  EXPECT_GT(through, 0);
}

}  // namespace
}  // namespace facet::rules

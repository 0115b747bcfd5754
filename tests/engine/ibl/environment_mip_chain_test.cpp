// The mip chain the filtered method reads: it keeps the map's integral over
// the sphere at every level, its lookups clamp to the chain, the level a
// sample reads follows its density, and the rule for the environment
// technique tells a sun from a soft sky.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/ibl/environment_lighting.h"
#include "engine/ibl/environment_lookup.h"
#include "rules/rules.h"
#include "engine/ibl/environment_mip_chain.h"
#include "tests/support/environment_maps.h"

namespace facet::ibl {
namespace {

namespace m = rules::f64;
using testing::mapOf;
using testing::skyWithSun;

glm::dvec3 levelIntegral(const MipLevel& level) {
  glm::dvec3 sum(0.0);
  for (int y = 0; y < level.height; ++y)
    for (int x = 0; x < level.width; ++x)
      sum += m::environment_texel_solid_angle(y, level.width, level.height) * texelAt(level.rgb.data(), level.width, x, y);
  return sum;
}

TEST(EnvironmentMipChain, EveryLevelKeepsTheIntegral) {
  const std::vector<MipLevel> chain = mipChain(mapOf(64, 32, skyWithSun));
  ASSERT_EQ(chain.size(), 6u);  // 64x32 ... 2x1
  EXPECT_EQ(chain.back().width, 2);
  EXPECT_EQ(chain.back().height, 1);
  const glm::dvec3 map = levelIntegral(chain.front());
  for (const MipLevel& level : chain)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(levelIntegral(level)[c], map[c], 1e-12 * map[c]) << level.width;
}

TEST(EnvironmentMipChain, LookupsBlendAdjacentLevelsAndClamp) {
  const std::vector<MipLevel> chain = mipChain(mapOf(32, 16, skyWithSun));
  const glm::dvec2 uv(0.3, 0.6);
  const glm::dvec3 fine = mipChainRadiance(chain, uv, 1), coarse = mipChainRadiance(chain, uv, 2);
  const glm::dvec3 between = mipChainRadiance(chain, uv, 1.25);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(between[c], 0.75 * fine[c] + 0.25 * coarse[c], 1e-12);
  EXPECT_EQ(mipChainRadiance(chain, uv, -3), mipChainRadiance(chain, uv, 0));
  EXPECT_EQ(mipChainRadiance(chain, uv, 40), mipChainRadiance(chain, uv, double(chain.size() - 1)));
}

// Omega_s = 4^k Omega_p reads level k + offset: each level's texels are 4 times larger.
TEST(EnvironmentMipChain, SampleLevelFollowsTheDensity) {
  const int width = 256, height = 128, levels = 8, samples = 16;
  const double omegaP = 4 * m::PI / (width * height);
  for (int k = 0; k < 6; ++k) {
    const double pdf = 1 / (samples * omegaP * std::pow(4.0, k));
    EXPECT_NEAR(m::mip_level_for_density(pdf, samples, width, height, levels, 1.0), k + 1, 1e-9) << k;
    EXPECT_NEAR(m::mip_level_for_density(pdf, samples, width, height, levels, 0.5), k + 0.5, 1e-9) << k;
  }
  EXPECT_EQ(m::mip_level_for_density(1e12, samples, width, height, levels, 1.0), 0);
  EXPECT_EQ(m::mip_level_for_density(0, samples, width, height, levels, 1.0), levels - 1);
}

TEST(EnvironmentMipChain, EnvironmentTechniqueOnlyUnderASun) {
  EXPECT_TRUE(filteredUsesEnvironmentSamples(mapOf(128, 64, skyWithSun)));
  EXPECT_FALSE(filteredUsesEnvironmentSamples(mapOf(128, 64, [](glm::dvec3 d) { return glm::dvec3(1.2 + d.y); })));
}

}  // namespace
}  // namespace facet::ibl

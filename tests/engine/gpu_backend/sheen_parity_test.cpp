// Sheen on the GPU (docs/shading.md, "Sheen"): a velvet ball under a punctual
// light and an environment, sampled with paths and prefiltered, matches the
// CPU reference; a kernel specialized for sheen shades a material without
// one bit for bit as the kernel without it; and the sheen brightens the
// ball's rim more than its centre.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

#include "tests/support/two_balls.h"

namespace facet {
namespace {

using testing::buildTestMaterial;

// A gold ball (no sheen) on the left, the velvet of scenes/examples/materials
// on the right (`sheen` false: its dark red base alone), lit by the sun and,
// with a method, the courtyard.
scene::Scene velvetBalls(bool sheen, std::optional<scene::IblMethod> method, int bounces) {
  materials::MaterialSpec velvet;
  velvet.fresnel = "schlick";
  velvet.f0 = glm::dvec3(0.04);
  velvet.diffuse = glm::dvec3(0.25, 0.02, 0.04);
  velvet.roughness = 0.8;
  if (sheen) velvet.sheenColor = glm::dvec3(0.9, 0.35, 0.4), velvet.sheenRoughness = 0.4;
  return testing::twoBalls(buildTestMaterial(velvet), method, bounces);
}

using GpuSheen = testing::GpuRenderTest;

TEST_F(GpuSheen, SampledPathsTraceTheCpuReferences) {
  testing::expectPathParity(testing::renderBoth(device_, velvetBalls(true, scene::IblMethod::Sampled, 2)),
                            {.median = 1e-4, .p98 = 2e-3, .parted = 5});
}

TEST_F(GpuSheen, PrefilteredSheenMatchesTheCpuReference) {
  testing::expectPathParity(testing::renderBoth(device_, velvetBalls(true, scene::IblMethod::Prefiltered, 0)),
                            {.median = 1e-4, .p98 = 1e-3, .parted = 0});
}

TEST_F(GpuSheen, ASheenedNeighbourLeavesOtherPixelsBitForBit) {
  // The left half sees only the gold ball. With a sheened neighbour the
  // kernel is specialized for sheen; without, it is not. Gold's pixels must
  // not change by one bit on either backend.
  const scene::Scene sheened = velvetBalls(true, scene::IblMethod::Prefiltered, 0);
  const scene::Scene bare = velvetBalls(false, scene::IblMethod::Prefiltered, 0);
  const testing::PathRenders a = testing::renderBoth(device_, sheened), b = testing::renderBoth(device_, bare);
  testing::expectLeftHalfBitForBit(a, b, sheened.render.width, sheened.render.height);
}

TEST_F(GpuSheen, TheSheenBrightensTheRimMoreThanTheCentre) {
  // The sun alone: velvet's sheen gathers at grazing views, so on the right
  // ball the rim's pixels gain more (relative to the bare base) than the
  // pixels facing the camera, on both backends.
  const testing::PathRenders sheened = testing::renderBoth(device_, velvetBalls(true, std::nullopt, 0));
  const testing::PathRenders bare = testing::renderBoth(device_, velvetBalls(false, std::nullopt, 0));
  const int width = 48, height = 24, cx = 36, cy = 12;  // the right ball's centre in pixels
  auto gain = [&](const std::vector<glm::vec4>& with, const std::vector<glm::vec4>& without, bool rim) {
    double a = 0, b = 0;
    for (int y = 0; y < height; ++y)
      for (int x = width / 2 + 2; x < width; ++x) {
        const std::size_t i = std::size_t(y * width + x);
        if (with[i].a < 1 || without[i].a < 1) continue;
        const int r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
        if (rim ? r2 < 36 : r2 > 9) continue;
        a += with[i].r, b += without[i].r;
      }
    return b > 0 ? a / b : 0.0;
  };
  for (bool gpu : {true, false}) {
    const auto& with = gpu ? sheened.gpu.image.beauty : sheened.reference.beauty;
    const auto& without = gpu ? bare.gpu.image.beauty : bare.reference.beauty;
    const double rim = gain(with, without, true), centre = gain(with, without, false);
    EXPECT_GT(rim, centre) << (gpu ? "gpu" : "cpu");
    EXPECT_GT(rim, 1.0) << (gpu ? "gpu" : "cpu");
    std::printf("%s: red gain from the sheen, rim %.3f, centre %.3f\n", gpu ? "gpu" : "cpu", rim, centre);
  }
}

}  // namespace
}  // namespace facet

// Clear coats on the GPU (docs/shading.md, "Clear coat"): a car paint and a
// glazed ceramic ball under a punctual light and an environment, sampled
// with paths and prefiltered, match the CPU reference; a kernel specialized
// for coats shades an uncoated material bit for bit as the kernel without
// them; and a smooth coat on a rough base adds a sharper, brighter highlight.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "tests/support/two_balls.h"

namespace facet {
namespace {

using testing::buildTestMaterial;

// A gold ball (uncoated) on the left, a red base of the given coat on the
// right (the car paint of scenes/examples/materials, its coat rougher to be
// resolved at 48 x 24), lit by the sun and, with a method, the courtyard.
scene::Scene coatedBalls(double clearcoat, std::optional<scene::IblMethod> method, int bounces) {
  materials::MaterialSpec paint;
  paint.fresnel = "schlick";
  paint.f0 = glm::dvec3(0.45, 0.06, 0.05);
  paint.diffuse = glm::dvec3(0.3, 0.01, 0.02);
  paint.roughness = 0.45;
  if (clearcoat > 0) paint.clearcoat = clearcoat, paint.clearcoatRoughness = 0.2;
  return testing::twoBalls(buildTestMaterial(paint), method, bounces);
}

using GpuClearcoat = testing::GpuRenderTest;

TEST_F(GpuClearcoat, SampledPathsTraceTheCpuReferences) {
  testing::expectPathParity(testing::renderBoth(device_, coatedBalls(1.0, scene::IblMethod::Sampled, 2)),
                            {.median = 1e-4, .p98 = 2e-3, .parted = 5});
}

TEST_F(GpuClearcoat, PrefilteredCoatMatchesTheCpuReference) {
  testing::expectPathParity(testing::renderBoth(device_, coatedBalls(1.0, scene::IblMethod::Prefiltered, 0)),
                            {.median = 1e-4, .p98 = 1e-3, .parted = 0});
}

TEST_F(GpuClearcoat, ACoatedNeighbourLeavesUncoatedPixelsBitForBit) {
  // The left half sees only the uncoated gold ball. With a coated neighbour
  // the kernel is specialized for coats; without, it is not. Gold's pixels
  // must not change by one bit on either backend.
  const scene::Scene coated = coatedBalls(1.0, scene::IblMethod::Prefiltered, 0);
  const scene::Scene bare = coatedBalls(0.0, scene::IblMethod::Prefiltered, 0);
  const testing::PathRenders a = testing::renderBoth(device_, coated), b = testing::renderBoth(device_, bare);
  testing::expectLeftHalfBitForBit(a, b, coated.render.width, coated.render.height);
}

TEST_F(GpuClearcoat, ASmoothCoatRaisesThePeakOfTheHighlight) {
  // The sun alone on the paint ball: its rough base spreads the highlight;
  // the coat of roughness 0.2 adds a narrow one at the mirror direction.
  // The brightest pixel of the right half must at least double, while the
  // ball's mean brightness changes little (the coat takes from the base what
  // it reflects), on both backends.
  const testing::PathRenders coated = testing::renderBoth(device_, coatedBalls(1.0, std::nullopt, 0));
  const testing::PathRenders bare = testing::renderBoth(device_, coatedBalls(0.0, std::nullopt, 0));
  const int width = 48, height = 24;
  auto peakAndMean = [&](const std::vector<glm::vec4>& beauty) {
    float peak = 0;
    double sum = 0;
    int count = 0;
    for (int y = 0; y < height; ++y)
      for (int x = width / 2 + 2; x < width; ++x) {
        const glm::vec4 c = beauty[std::size_t(y * width + x)];
        if (c.a <= 0) continue;
        const float luminance = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
        peak = std::max(peak, luminance);
        sum += luminance;
        ++count;
      }
    return std::pair{peak, sum / std::max(count, 1)};
  };
  for (bool gpu : {true, false}) {
    const auto [coatedPeak, coatedMean] = peakAndMean(gpu ? coated.gpu.image.beauty : coated.reference.beauty);
    const auto [barePeak, bareMean] = peakAndMean(gpu ? bare.gpu.image.beauty : bare.reference.beauty);
    EXPECT_GT(coatedPeak, 2 * barePeak) << (gpu ? "gpu" : "cpu");
    EXPECT_NEAR(coatedMean, bareMean, 0.5 * bareMean) << (gpu ? "gpu" : "cpu");
    std::printf("%s: highlight peak %.4f bare, %.4f coated; mean %.4f bare, %.4f coated\n", gpu ? "gpu" : "cpu",
                barePeak, coatedPeak, bareMean, coatedMean);
  }
}

}  // namespace
}  // namespace facet

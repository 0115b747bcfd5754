// Iridescence on the GPU (docs/shading.md, "Iridescence"): a ball of a
// filmed dark metal under a punctual light and an environment, sampled with
// paths and prefiltered, matches the CPU reference; a kernel specialized
// for the film shades a material without one bit for bit as the kernel
// without it; and the film colours the ball by its thickness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "tests/support/two_balls.h"

namespace facet {
namespace {

using testing::buildTestMaterial;

// A gold ball (no film) on the left, on the right a grey metal under a film
// `nm` thick (0: none), lit by the sun and, with a method, the courtyard.
scene::Scene filmedBalls(double nm, std::optional<scene::IblMethod> method, int bounces) {
  materials::MaterialSpec metal;
  metal.fresnel = "schlick";
  metal.f0 = glm::dvec3(0.5);
  metal.roughness = 0.3;
  if (nm > 0) metal.iridescence = 1.0, metal.iridescenceIor = 1.5, metal.iridescenceThickness = nm;
  return testing::twoBalls(buildTestMaterial(metal), method, bounces);
}

using GpuIridescence = testing::GpuRenderTest;

TEST_F(GpuIridescence, SampledPathsTraceTheCpuReferences) {
  testing::expectPathParity(testing::renderBoth(device_, filmedBalls(300, scene::IblMethod::Sampled, 2)),
                            {.median = 1e-4, .p98 = 2e-3, .parted = 5});
}

TEST_F(GpuIridescence, PrefilteredIridescenceMatchesTheCpuReference) {
  testing::expectPathParity(testing::renderBoth(device_, filmedBalls(300, scene::IblMethod::Prefiltered, 0)),
                            {.median = 1e-4, .p98 = 1e-3, .parted = 0});
}

TEST_F(GpuIridescence, AFilmedNeighbourLeavesOtherPixelsBitForBit) {
  const scene::Scene filmed = filmedBalls(300, scene::IblMethod::Prefiltered, 0);
  const scene::Scene bare = filmedBalls(0, scene::IblMethod::Prefiltered, 0);
  const testing::PathRenders a = testing::renderBoth(device_, filmed), b = testing::renderBoth(device_, bare);
  testing::expectLeftHalfBitForBit(a, b, filmed.render.width, filmed.render.height);
}

TEST_F(GpuIridescence, TheFilmColoursTheGreyMetalByItsThickness) {
  // Under the sun alone the bare metal is grey; films of 250 and 450 nm
  // tint it, each its own way, on both backends.
  const auto tint = [](const std::vector<glm::vec4>& beauty, int width) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < beauty.size(); ++i)
      if (int(i) % width > width / 2 + 2 && beauty[i].a == 1.0f) sum += glm::dvec3(beauty[i]);
    return sum / std::max(1e-30, (sum.x + sum.y + sum.z) / 3.0);  // colour at unit mean
  };
  const int width = filmedBalls(0, std::nullopt, 0).render.width;
  const testing::PathRenders bare = testing::renderBoth(device_, filmedBalls(0, std::nullopt, 0));
  const testing::PathRenders thin = testing::renderBoth(device_, filmedBalls(250, std::nullopt, 0));
  const testing::PathRenders thick = testing::renderBoth(device_, filmedBalls(450, std::nullopt, 0));
  for (const bool gpu : {false, true}) {
    const auto image = [&](const testing::PathRenders& r) { return gpu ? r.gpu.image.beauty : r.reference.beauty; };
    const glm::dvec3 grey = tint(image(bare), width), a = tint(image(thin), width), b = tint(image(thick), width);
    std::printf("%s colour at unit mean: bare %.3f %.3f %.3f, 250 nm %.3f %.3f %.3f, 450 nm %.3f %.3f %.3f\n",
                gpu ? "gpu" : "cpu", grey.x, grey.y, grey.z, a.x, a.y, a.z, b.x, b.y, b.z);
    EXPECT_LT(glm::length(grey - glm::dvec3(1.0)), 0.01);
    EXPECT_GT(glm::length(a - grey), 0.1);
    EXPECT_GT(glm::length(b - grey), 0.1);
    EXPECT_GT(glm::length(a - b), 0.1);
  }
}

}  // namespace
}  // namespace facet

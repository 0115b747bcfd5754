// Anisotropic materials on the GPU (docs/shading.md, "Anisotropy"): brushed
// balls under a punctual light and an environment, sampled with paths and
// prefiltered, trace the CPU reference's tangent field and lobes; and a
// kernel specialized for anisotropy shades an isotropic material bit for
// bit as the kernel without it.
#include <gtest/gtest.h>

#include "tests/support/two_balls.h"

namespace facet {
namespace {

using testing::buildTestMaterial;

// A gold ball (isotropic) on the left, a brushed aluminium one of the given
// anisotropy on the right, lit by the sun and the courtyard.
scene::Scene brushedBalls(double anisotropy, scene::IblMethod method, int bounces) {
  materials::MaterialSpec aluminium;
  aluminium.preset = "aluminum";
  aluminium.roughness = 0.3;
  aluminium.anisotropy = anisotropy;
  aluminium.anisotropyRotation = 0.6;
  aluminium.diffuse = glm::dvec3(0.05);
  return testing::twoBalls(buildTestMaterial(aluminium), method, bounces);
}

using GpuAnisotropy = testing::GpuRenderTest;

TEST_F(GpuAnisotropy, SampledPathsTraceTheCpuReferences) {
  testing::expectPathParity(testing::renderBoth(device_, brushedBalls(0.8, scene::IblMethod::Sampled, 2)),
                            {.median = 1e-4, .p98 = 2e-3, .parted = 5});
}

TEST_F(GpuAnisotropy, PrefilteredBentNormalMatchesTheCpuReference) {
  testing::expectPathParity(testing::renderBoth(device_, brushedBalls(0.8, scene::IblMethod::Prefiltered, 0)),
                            {.median = 1e-4, .p98 = 1e-3, .parted = 0});
}

TEST_F(GpuAnisotropy, AnAnisotropicNeighbourLeavesIsotropicPixelsBitForBit) {
  // The left half sees only the isotropic gold ball (its shadow rays test
  // the other ball's geometry, which anisotropy does not change). With an
  // anisotropic neighbour the kernel is specialized for anisotropy; without,
  // it is not. Gold's pixels must not change by one bit on either backend.
  const scene::Scene anisotropic = brushedBalls(0.8, scene::IblMethod::Prefiltered, 0);
  const scene::Scene isotropic = brushedBalls(0.0, scene::IblMethod::Prefiltered, 0);
  const testing::PathRenders a = testing::renderBoth(device_, anisotropic), b = testing::renderBoth(device_, isotropic);
  testing::expectLeftHalfBitForBit(a, b, anisotropic.render.width, anisotropic.render.height);
  // The right half did change: the neighbour is anisotropic.
  double changed = 0;
  for (std::size_t i = 0; i < a.gpu.image.beauty.size(); ++i)
    changed += glm::length(glm::dvec3(a.gpu.image.beauty[i]) - glm::dvec3(b.gpu.image.beauty[i]));
  EXPECT_GT(changed, 0.1);
}

}  // namespace
}  // namespace facet

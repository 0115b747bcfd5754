// Anisotropic materials on the GPU (docs/shading.md, "Anisotropy"): brushed
// balls under a punctual light and an environment, sampled with paths and
// prefiltered, trace the CPU reference's tangent field and lobes; and a
// kernel specialized for anisotropy shades an isotropic material bit for
// bit as the kernel without it.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <memory>

#include "scenes/environment_map.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/path_parity.h"

namespace facet {
namespace {

using testing::buildTestMaterial;

// A gold ball (isotropic) on the left, a brushed aluminium one of the given
// anisotropy on the right, lit by the sun and the courtyard.
scene::Scene brushedBalls(double anisotropy, scene::IblMethod method, int bounces) {
  scene::Scene s;
  materials::MaterialSpec gold;
  gold.preset = "gold";
  gold.roughness = 0.4;
  s.materials.push_back(buildTestMaterial(gold));
  materials::MaterialSpec aluminium;
  aluminium.preset = "aluminum";
  aluminium.roughness = 0.3;
  aluminium.anisotropy = anisotropy;
  aluminium.anisotropyRotation = 0.6;
  aluminium.diffuse = glm::dvec3(0.05);
  s.materials.push_back(buildTestMaterial(aluminium));
  scene::ControlCage left = testing::uvSphereCage(8, 16), right = testing::uvSphereCage(8, 16);
  for (glm::dvec3& p : left.positions) p += glm::dvec3(-1.1, 0.0, 0.0);
  for (glm::dvec3& p : right.positions) p += glm::dvec3(1.1, 0.0, 0.0);
  s.objects.push_back(testing::testObject("gold", std::move(left), 0));
  s.objects.push_back(testing::testObject("aluminium", std::move(right), 1));
  s.objects.back().subdivision = scene::Subdivision::CatmullClark;
  s.objects.front().subdivision = scene::Subdivision::CatmullClark;
  scene::Light sun;
  sun.direction = glm::normalize(glm::dvec3(-0.4, -0.6, -1.0));
  sun.color = glm::dvec3(2.0);
  s.lights.push_back(sun);
  s.camera.eye = {0.0, 0.5, 5.0};
  s.camera.verticalFovDegrees = 36.0;
  s.render.width = 48;
  s.render.height = 24;
  s.render.samplesPerPixel = 4;
  s.render.bounces = bounces;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / "courtyard_256x128.hdr"));
  s.environment->method = method;
  s.environment->occlusion = method == scene::IblMethod::Sampled;
  s.environment->samples = 2;
  return s;
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
  const int width = anisotropic.render.width;
  int compared = 0, covered = 0;
  for (int y = 0; y < anisotropic.render.height; ++y)
    for (int x = 0; x < width / 2 - 2; ++x) {
      const std::size_t i = std::size_t(y * width + x);
      EXPECT_EQ(std::memcmp(&a.gpu.image.beauty[i], &b.gpu.image.beauty[i], sizeof(glm::vec4)), 0) << x << "," << y;
      EXPECT_EQ(std::memcmp(&a.reference.beauty[i], &b.reference.beauty[i], sizeof(glm::vec4)), 0) << x << "," << y;
      covered += a.gpu.image.beauty[i].a > 0 ? 1 : 0;
      ++compared;
    }
  EXPECT_GT(covered, compared / 8);  // the gold ball is in the compared half
  // The right half did change: the neighbour is anisotropic.
  double changed = 0;
  for (std::size_t i = 0; i < a.gpu.image.beauty.size(); ++i)
    changed += glm::length(glm::dvec3(a.gpu.image.beauty[i]) - glm::dvec3(b.gpu.image.beauty[i]));
  EXPECT_GT(changed, 0.1);
}

}  // namespace
}  // namespace facet

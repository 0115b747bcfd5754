// The front-end's decision that a scene's paths cannot continue
// (scenes/path_reach.h), on both backends: a convex cage under an environment
// at 8 bounces casts no continuation ray and renders the image of 0 bounces
// byte for byte; a concave one still bounces.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "engine/cpu/reference_renderer.h"
#include "engine/renderer.h"
#include "scenes/scene_geometry.h"
#include "scenes/obj_cage.h"
#include "tests/support/blob_scene.h"
#include "tests/support/cages.h"
#include "tests/support/environment_maps.h"
#include "tests/support/inside_sphere.h"

namespace facet {
namespace {

scene::Scene underSky(scene::ControlCage cage, int bounces) {
  scene::Scene s = testing::blobUnder(
      testing::lambertian(0.8),
      std::make_shared<const scene::EnvironmentMap>(ibl::testing::mapOf(64, 32, ibl::testing::skyWithSun)), 24);
  s.objects.front().cage = std::move(cage);
  s.render.method = scene::IntersectionMethod::Exact;
  s.render.samplesPerPixel = 4;
  s.render.bounces = bounces;
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->samples = 4;
  return s;
}

scene::ControlCage cubeCage() { return scene::loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj"); }

void expectSameImage(const Image& a, const Image& b) {
  ASSERT_EQ(a.pixelCount(), b.pixelCount());
  for (std::size_t p = 0; p < a.pixelCount(); ++p) {
    ASSERT_EQ(a.beauty[p], b.beauty[p]) << p;
    ASSERT_EQ(a.depth[p], b.depth[p]) << p;
    ASSERT_EQ(a.shadingNormal[p], b.shadingNormal[p]) << p;
    ASSERT_EQ(a.patchId[p], b.patchId[p]) << p;
  }
}

// One Renderer for the suite, ended before the process unloads Vulkan (engine/renderer.h).
class RendererPaths : public ::testing::TestWithParam<Backend> {
 protected:
  static void SetUpTestSuite() { shared_ = std::make_unique<Renderer>(); }
  static void TearDownTestSuite() { shared_.reset(); }
  static Renderer& renderer() { return *shared_; }

 private:
  static inline std::unique_ptr<Renderer> shared_;
};

TEST_P(RendererPaths, AConvexObjectCastsNoContinuationAndRendersZeroBouncesImage) {
  const RenderReport paths = renderer().render(underSky(cubeCage(), 8), GetParam());
  const RenderReport direct = renderer().render(underSky(cubeCage(), 0), GetParam());
  std::printf("%s: %s\n", toString(GetParam()), paths.lightTransport.note.c_str());
  EXPECT_EQ(paths.lightTransport.note, "paths: none cast: one convex closed object, seen from outside; no continuation can hit");
  EXPECT_NE(paths.geometrySummary.find(paths.lightTransport.note), std::string::npos);
  EXPECT_TRUE(paths.raysPerBounce.empty());
  EXPECT_EQ(paths.shadowRays, direct.shadowRays);
  EXPECT_TRUE(direct.lightTransport.note.empty());
  expectSameImage(paths.image, direct.image);
}

// The premise, checked by tracing anyway: the CPU reference, called without
// the front-end, sends the cube's continuations and none of them hits.
TEST(RendererPathsPremise, TheCubesContinuationsAllMiss) {
  const scene::Scene s = underSky(cubeCage(), 8);
  cpu::ReferenceStatistics statistics;
  cpu::renderReference(s, scene::buildGeometry(s), &statistics);
  ASSERT_EQ(statistics.raysPerBounce.size(), 9u);
  std::printf("traced anyway: bounce 1 %llu continuation rays, %llu hit\n",
              (unsigned long long)statistics.raysPerBounce[1].rays,
              (unsigned long long)statistics.raysPerBounce[1].hits);
  EXPECT_GT(statistics.raysPerBounce[1].rays, 1000u);
  EXPECT_EQ(statistics.raysPerBounce[1].hits, 0u);
}

TEST_P(RendererPaths, AConcaveObjectStillBounces) {
  scene::Scene s = underSky(scene::testing::torusCage(12, 8, 1.0, 0.4), 2);
  s.camera.eye = {0.0, 2.5, 3.0};
  s.camera.target = {0.0, 0.0, 0.0};
  const RenderReport report = renderer().render(s, GetParam());
  EXPECT_TRUE(report.lightTransport.note.empty());
  ASSERT_EQ(report.raysPerBounce.size(), 3u);
  std::printf("%s torus: bounce 1 %llu rays, %llu hit\n", toString(GetParam()),
              (unsigned long long)report.raysPerBounce[1].rays, (unsigned long long)report.raysPerBounce[1].hits);
  EXPECT_GT(report.raysPerBounce[1].hits, 10u);
}

TEST_P(RendererPaths, AnEyeInsideAConvexSphereStillBounces) {
  scene::Scene s = testing::insideDiffuseSphere(0.5, 1, 16, 1);
  s.render.method = scene::IntersectionMethod::Exact;
  const RenderReport report = renderer().render(s, GetParam());
  EXPECT_TRUE(report.lightTransport.note.empty());
  ASSERT_EQ(report.raysPerBounce.size(), 2u);
  EXPECT_EQ(report.raysPerBounce[1].hits, report.raysPerBounce[1].rays);  // closed: every continuation hits
  EXPECT_GT(report.raysPerBounce[1].rays, 0u);
}

// Glass left to choose is glass (scenes/light_transport.h): under a white
// sky a clear cube passes most of the light behind it, where the direct
// light alone shows its reflection only; and the choice renders what
// Cycles' limits, stated, render.
TEST_P(RendererPaths, GlassLeftToChooseShowsWhatIsBehindIt) {
  scene::Scene s = underSky(cubeCage(), 0);
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  s.materials.front().transmission = 1.0;
  s.materials.front().diffuse = glm::dvec3(0.0);
  s.materials.front().name = "glass";
  s.environment->method = scene::IblMethod::Prefiltered;
  s.environment->methodStated = false;
  s.environment->samples = 1;  // a uniform sky: little noise to average
  s.render.samplesPerPixel = 1;
  s.render.bouncesStated = false;
  const RenderReport chosen = renderer().render(s, GetParam());
  s.render.bouncesStated = true;
  const RenderReport direct = renderer().render(s, GetParam());
  // The choice is Cycles' limits with the environment sampled, stated or not.
  s.render.bounces = 12;
  s.render.diffuseBounces = 4;
  s.render.glossyBounces = 4;
  s.render.transmissionBounces = 12;
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->methodStated = true;
  expectSameImage(renderer().render(s, GetParam()).image, chosen.image);
  auto coveredMean = [](const Image& image) {
    double sum = 0;
    std::size_t covered = 0;
    for (std::size_t p = 0; p < image.pixelCount(); ++p)
      if (std::isfinite(image.depth[p])) sum += image.beauty[p].g, ++covered;
    return sum / double(covered);
  };
  std::printf("%s glass: chosen %s, mean %.3f; stated 0 bounces, mean %.3f\n", toString(GetParam()),
              chosen.lightTransport.note.c_str(), coveredMean(chosen.image), coveredMean(direct.image));
  EXPECT_EQ(chosen.lightTransport.bounces, 12);
  EXPECT_GT(coveredMean(chosen.image), 0.6);
  EXPECT_LT(coveredMean(direct.image), 0.3);
  ASSERT_EQ(direct.warnings.size(), 1u);
  EXPECT_NE(direct.warnings.front().find("'glass' transmits"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(BothBackends, RendererPaths, ::testing::Values(Backend::Cpu, Backend::Gpu),
                         [](const ::testing::TestParamInfo<Backend>& info) {
                           return std::string(toString(info.param));
                         });

}  // namespace
}  // namespace facet

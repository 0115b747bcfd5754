// The preview's ground in the paths (docs/preview-stage.md, "The ground in
// the paths"): camera rays pass over the shadow catcher and see a held-out
// model black on both backends, a mirror ball shows the share of the open
// sky its own shadow leaves the ground, as the form factor of a sphere gives
// it, and the GPU traces the CPU reference's paths through the catcher.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <cmath>
#include <cstdio>

#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/ground_plane.h"
#include "scenes/scene_geometry.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/gpu_device.h"
#include "tests/support/inside_sphere.h"
#include "tests/support/path_parity.h"
#include "tests/support/preview_objects.h"

namespace facet {
namespace {

using GpuShadowCatcher = testing::GpuRenderTest;

scene::Scene withCatcher(const scene::Scene& model) {
  return scene::withShadowCatcher(model, scene::groundScenes(model));
}

// Where a camera ray would meet the ground, it sees what it saw without
// one, and the model covers exactly the pixels it covered.
void expectCameraPassesOver(const Image& open, const Image& caught) {
  ASSERT_EQ(open.pixelCount(), caught.pixelCount());
  int background = 0;
  for (std::size_t p = 0; p < open.pixelCount(); ++p) {
    ASSERT_EQ(caught.beauty[p].a, open.beauty[p].a) << p;
    if (open.beauty[p].a > 0.0f) continue;
    ++background;
    ASSERT_EQ(caught.beauty[p], open.beauty[p]) << p;
    ASSERT_EQ(caught.depth[p], open.depth[p]) << p;
  }
  EXPECT_GT(background, int(open.pixelCount() / 4));
}

TEST_F(GpuShadowCatcher, CameraRaysPassOverItOnBothBackends) {
  const scene::Scene open = testing::previewWithPaths(scene::IntersectionMethod::Tessellated, 2),
                     caught = withCatcher(open);
  {
    SCOPED_TRACE("cpu");
    expectCameraPassesOver(cpu::renderReference(open, scene::buildGeometry(open)),
                           cpu::renderReference(caught, scene::buildGeometry(caught)));
  }
  SCOPED_TRACE("gpu");
  expectCameraPassesOver(render(open).image, render(caught).image);
}

TEST_F(GpuShadowCatcher, TracesTheCpuReferencesPathsThroughIt) {
  const scene::Scene open = testing::previewWithPaths(scene::IntersectionMethod::Tessellated, 3),
                     caught = withCatcher(open);
  const testing::PathRenders r = testing::renderBoth(device_, caught);
  cpu::ReferenceStatistics without;
  cpu::renderReference(open, scene::buildGeometry(open), &without);
  // The continuations that left the model downwards now meet the ground.
  EXPECT_GT(r.cpuRays.raysPerBounce.at(1).hits, without.raysPerBounce.at(1).hits + 50);
  // A continuation that leaves the model just below the horizon meets the
  // ground far off at a grazing angle, or passes its edge: float and double
  // part there more often than at the model's silhouettes, and a parted path
  // moves its pixel (of one sample) by all it carries. The means agree.
  testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-2, .mean = 3e-3});
}

// The holdout with paths (scene::holdoutWithPaths) against the same scene
// with nothing held out: camera rays that hit the model see black and count
// as covered, and every pixel of the ground alone is unchanged, since its
// continuations still find the model in its materials.
void expectHeldOut(const Image& shown, const Image& heldOut) {
  ASSERT_EQ(shown.pixelCount(), heldOut.pixelCount());
  int black = 0, same = 0;
  for (std::size_t p = 0; p < shown.pixelCount(); ++p) {
    ASSERT_EQ(heldOut.beauty[p].a, shown.beauty[p].a) << p;
    const glm::vec3 h(heldOut.beauty[p]), s(shown.beauty[p]);
    if (h == s) {
      ++same;
      continue;
    }
    // A pixel whose samples met the model: only what they brought is gone.
    ASSERT_TRUE(glm::all(glm::lessThanEqual(h, s + 1e-6f))) << p;
    if (h == glm::vec3(0.0f) && heldOut.beauty[p].a == 1.0f) ++black;
  }
  EXPECT_GT(black, int(shown.pixelCount() / 20));
  EXPECT_GT(same, int(shown.pixelCount() / 2));
}

TEST_F(GpuShadowCatcher, AHeldOutModelIsBlackToTheCameraAndSeenByThePaths) {
  const scene::Scene model = testing::previewWithPaths(scene::IntersectionMethod::Tessellated, 2);
  const scene::Scene heldOut = scene::holdoutWithPaths(scene::groundScenes(model), model);
  scene::Scene shown = heldOut;
  for (scene::Object& object : shown.objects) object.holdout = false;
  {
    SCOPED_TRACE("cpu");
    expectHeldOut(cpu::renderReference(shown, scene::buildGeometry(shown)),
                  cpu::renderReference(heldOut, scene::buildGeometry(heldOut)));
  }
  SCOPED_TRACE("gpu");
  expectHeldOut(render(shown).image, render(heldOut).image);
  testing::expectPathParity(testing::renderBoth(device_, heldOut), {.median = 1e-4, .p98 = 2e-2, .mean = 3e-3});
}

// A mirror ball standing on the catcher under a uniform white sky. The
// ground at x receives the sky less the ball, whose cosine-weighted solid
// angle is the form factor of a sphere of radius R at distance d from x,
// (R / d)^2 cos theta (theta from the ground's normal to the ball's
// centre); so the catcher shows the background, 1, times s = 1 - (R / d)^2
// cos theta, and the ball shows it wherever it reflects the ground. The GPU
// traces the same paths.
TEST_F(GpuShadowCatcher, AMirrorBallShowsTheOpenSkyItsShadowLeavesTheGround) {
  materials::Material mirror = scene::defaultMaterial();
  mirror.f0 = glm::dvec3(1.0);
  mirror.alpha = 1e-4;
  mirror.diffuse = glm::dvec3(0.0);
  scene::Scene ball = testing::underWhite(mirror, testing::uvSphereCage(16, 32), 4, 64, 30);
  ball.objects[0].subdivision = scene::Subdivision::CatmullClark;
  ball.camera.eye = {0.0, 0.6, 4.0};
  ball.environment->occlusion = true;
  ball.environment->samples = 2;
  ball.render.samplesPerPixel = 64;
  const scene::SceneGeometry geometry = scene::buildGeometry(ball);
  const double radius = -scene::lowestPoint(geometry);  // the limit surface's, about the cage's centre
  const scene::Scene caught = withCatcher(ball);
  const testing::PathRenders both = testing::renderBoth(device_, caught);
  testing::expectPathParity(both, {.median = 1e-5, .p98 = 1e-4, .parted = 40, .mean = 1e-4});
  const Image& image = both.reference;

  const glm::dvec3 centre(0.0);
  double rendered = 0, expected = 0, darkest = 1;
  int pixels = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t p = image.index(x, y);
      if (image.beauty[p].a < 1.0f) continue;  // the ball's silhouette
      const glm::dvec3 hit(image.position[p]), n = glm::normalize(glm::dvec3(image.shadingNormal[p]));
      const glm::dvec3 view = glm::normalize(hit - ball.camera.eye);
      const glm::dvec3 reflected = glm::reflect(view, n);
      if (reflected.y > -0.2) continue;  // the sky, or the ground near its horizon
      const glm::dvec3 ground = hit + reflected * ((-radius - hit.y) / reflected.y);
      const glm::dvec3 toCentre = centre - ground;
      const double d = glm::length(toCentre);
      const double share = 1.0 - radius * radius / (d * d) * (toCentre.y / d);
      rendered += image.beauty[p].r;
      expected += share;
      darkest = std::min(darkest, share);
      ++pixels;
    }
  std::printf("mirror ball: %d pixels reflect the ground; mean %.5f, form factor's %.5f, darkest %.3f\n", pixels,
              rendered / pixels, expected / pixels, darkest);
  ASSERT_GT(pixels, 100);
  EXPECT_LT(darkest, 0.7);  // the reflection reaches into the shadow
  EXPECT_NEAR(rendered / pixels, expected / pixels, 0.01 * expected / pixels);
}

}  // namespace
}  // namespace facet

// The preview's ground: where it stands and how its scenes are lit, and, on
// the GPU backend, a blob over it under light from overhead: the ground
// right under the blob is darker than the background by a real margin, the
// far ground is the background within noise, the sky and the blob's own
// pixels are exactly the ground-less render's.
#include "engine/ground_plane.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "engine/adaptive_render.h"
#include "tests/support/blob_scene.h"
#include "tests/support/environment_maps.h"

namespace facet {
namespace {

// A dim floor and sky with a broad light overhead.
std::shared_ptr<const scene::EnvironmentMap> overheadLight() {
  return std::make_shared<const scene::EnvironmentMap>(ibl::testing::mapOf(
      32, 16, [](glm::dvec3 d) { return glm::dvec3(0.1 + 4.0 * std::pow(std::max(d.y, 0.0), 8.0)); }));
}

// Seen from far enough that the ground reaches from under the blob to
// several of its widths in front of it, and the sky shows above.
scene::Scene blob() {
  scene::Scene s = testing::blobUnder(testing::lambertian(0.7), overheadLight(), 48);
  s.camera.eye = {0.0, 2.0, 9.0};
  s.camera.verticalFovDegrees = 40;
  return s;
}

TEST(GroundPlane, TouchesTheLowestPointOfTheLimitSurface) {
  const scene::Scene model = blob();
  const scene::SceneGeometry geometry = scene::buildGeometry(model);
  const double lowest = lowestPoint(geometry);
  EXPECT_GE(lowest, geometry.bounds.lo.y) << "the patches' hulls hold the surface";
  EXPECT_LT(lowest, geometry.bounds.lo.y + 0.01 * geometry.bounds.diagonal());
  const GroundScenes scenes = groundScenes(model);
  ASSERT_EQ(scenes.ground.objects.size(), 1u);
  for (const glm::dvec3& p : scenes.ground.objects[0].cage.positions) EXPECT_DOUBLE_EQ(p.y, lowest);
  ASSERT_EQ(scenes.holdout.objects.size(), 2u);
  EXPECT_EQ(scenes.holdout.objects[0].cage.positions, model.objects[0].cage.positions);
  EXPECT_EQ(scenes.holdout.objects[1].cage.positions, scenes.ground.objects[0].cage.positions);
}

TEST(GroundPlane, IsLitWithShadowRays) {
  scene::Scene model = blob();
  model.environment->occlusion = false;
  const GroundScenes prefiltered = groundScenes(model);
  EXPECT_EQ(prefiltered.ground.environment->method, scene::IblMethod::Filtered);
  EXPECT_EQ(prefiltered.holdout.environment->method, scene::IblMethod::Filtered);
  EXPECT_TRUE(prefiltered.holdout.environment->occlusion);
  // The ground alone has nothing to block its light: its shadow rays could
  // only pass, so it casts none and draws the same samples.
  EXPECT_FALSE(prefiltered.ground.environment->occlusion);
  model.environment->method = scene::IblMethod::Sampled;
  EXPECT_EQ(groundScenes(model).holdout.environment->method, scene::IblMethod::Sampled);
  const materials::Material& holdout =
      prefiltered.holdout.materials[std::size_t(prefiltered.holdout.objects[0].material)];
  EXPECT_EQ(holdout.diffuse, glm::dvec3(0.0));
  EXPECT_EQ(holdout.fresnel, rules::f64::F_DIELECTRIC);
  EXPECT_EQ(holdout.eta, glm::dvec3(1.0)) << "no interface: it reflects nothing";
  model.environment.reset();
  EXPECT_THROW(groundScenes(model), std::invalid_argument);
}

float luminance3(const glm::vec4& p) { return 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b; }

TEST(GroundPlane, CatchesTheBlobsShadowAndIsOtherwiseUnseen) {
  const scene::Scene model = blob();
  const GroundScenes ground = groundScenes(model);
  // Two rounds for every tile, with or without the ground: the same samples.
  // No time limit (the default), so that load cannot cut either render short.
  AdaptiveSettings settings;
  settings.maxSpp = 8;
  settings.noiseThreshold = 1e-4;
  settings.tileSize = 8;
  Renderer renderer;
  const AdaptiveReport bareReport = renderAdaptive(renderer, model, Backend::Gpu, settings);
  const AdaptiveReport caughtReport = renderAdaptive(renderer, model, Backend::Gpu, settings, 0, &ground);
  for (const AdaptiveReport* r : {&bareReport, &caughtReport}) {
    ASSERT_EQ(r->stop, AdaptiveStop::SampleCap);
    ASSERT_EQ(r->rounds, 2);
  }
  const Image& bare = bareReport.image;
  const Image& caught = caughtReport.image;
  const int w = bare.width, h = bare.height;

  int lowestRow = -1;  // of the blob, in the middle column
  for (int y = 0; y < h; ++y)
    if (bare.beauty[bare.index(w / 2, y)].a > 0.99f) lowestRow = y;
  ASSERT_GT(lowestRow, 0);
  ASSERT_LT(lowestRow, h - 3) << "ground shows below the blob";
  for (int y = lowestRow + 1; y <= lowestRow + 2; ++y) {
    const std::size_t i = bare.index(w / 2, y);
    EXPECT_LT(luminance3(caught.beauty[i]), 0.6f * luminance3(bare.beauty[i])) << "under the blob, row " << y;
  }
  int same = 0, covered = 0;
  for (std::size_t i = 0; i < bare.pixelCount(); ++i) {
    if (bare.beauty[i].a < 1.0f) continue;
    ++covered;
    same += caught.beauty[i] == bare.beauty[i];
  }
  EXPECT_GT(covered, 20);
  EXPECT_EQ(same, covered) << "the blob's pixels are the ground-less render's";
  for (int x = 0; x < w; ++x) {
    const std::size_t sky = bare.index(x, 0), near = bare.index(x, h - 1);
    EXPECT_EQ(caught.beauty[sky], bare.beauty[sky]) << "above the horizon, column " << x;
    EXPECT_NEAR(luminance3(caught.beauty[near]), luminance3(bare.beauty[near]), 0.05f * luminance3(bare.beauty[near]))
        << "the ground far from the blob, column " << x;
  }
}

}  // namespace
}  // namespace facet

// The adaptive renderer with the preview's ground (scenes/ground_plane.h), on
// the GPU backend, a blob over it under light from overhead: the ground
// right under the blob is darker than the background by a real margin, the
// far ground is the background within noise, the sky and the blob's own
// pixels are exactly the ground-less render's. Where paths run, a glass
// blob sees the ground and its shadow is lighter than an opaque one's
// (docs/preview-stage.md, "The ground in the paths").
#include "engine/adaptive_render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/glass_scenes.h"
#include "tests/support/ground_blob.h"

namespace facet {
namespace {

float luminance3(const glm::vec4& p) { return 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b; }

// Two rounds of 4 samples for every tile: the same samples in every render.
// No time limit (the default), so that load cannot cut a render short.
AdaptiveSettings twoRounds() {
  AdaptiveSettings settings;
  settings.maxSpp = 8;
  settings.noiseThreshold = 1e-4;
  settings.tileSize = 8;
  return settings;
}

// The lowest row of the blob in the middle column.
int lowestRow(const Image& image) {
  int lowest = -1;
  for (int y = 0; y < image.height; ++y)
    if (image.beauty[image.index(image.width / 2, y)].a > 0.99f) lowest = y;
  return lowest;
}

TEST(GroundPlane, CatchesTheBlobsShadowAndIsOtherwiseUnseen) {
  const scene::Scene model = testing::blobOverGround();
  const scene::GroundScenes ground = scene::groundScenes(model);
  const AdaptiveSettings settings = twoRounds();
  Renderer renderer;
  const AdaptiveReport bareReport = renderAdaptive(renderer, model, Backend::Gpu, settings);
  const AdaptiveReport caughtReport = renderAdaptive(renderer, model, Backend::Gpu, settings, {}, {}, &ground);
  for (const AdaptiveReport* r : {&bareReport, &caughtReport}) {
    ASSERT_EQ(r->stop, AdaptiveStop::SampleCap);
    ASSERT_EQ(r->rounds, 2);
  }
  const Image& bare = bareReport.image;
  const Image& caught = caughtReport.image;
  const int w = bare.width, h = bare.height;

  const int lowest = lowestRow(bare);
  ASSERT_GT(lowest, 0);
  ASSERT_LT(lowest, h - 3) << "ground shows below the blob";
  for (int y = lowest + 1; y <= lowest + 2; ++y) {
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

TEST(GroundPlane, WithPathsGlassSeesTheGroundAndCastsALighterShadow) {
  scene::Scene glass = testing::blobOverGround();
  glass.materials[0] = testing::buildTestMaterial(testing::glassSpec(1.5));
  glass.environment->method = scene::IblMethod::Sampled;
  glass.environment->occlusion = true;
  glass.environment->samples = 2;
  glass.render.bounces = 8;
  scene::Scene direct = glass;
  direct.render.bounces = 0;
  const scene::GroundScenes ground = scene::groundScenes(glass);
  Renderer renderer;
  const Image paths = renderAdaptive(renderer, glass, Backend::Gpu, twoRounds(), {}, {}, &ground).image;
  const Image bare = renderAdaptive(renderer, glass, Backend::Gpu, twoRounds()).image;
  const Image opaque = renderAdaptive(renderer, direct, Backend::Gpu, twoRounds(), {}, {}, &ground).image;
  const int w = paths.width, lowest = lowestRow(paths);
  ASSERT_GT(lowest, 0);
  ASSERT_LT(lowest, paths.height - 3) << "ground shows below the blob";
  // Light through the glass lands in its shadow.
  for (int y = lowest + 1; y <= lowest + 2; ++y) {
    const std::size_t i = paths.index(w / 2, y);
    EXPECT_GT(luminance3(paths.beauty[i]), 1.3f * luminance3(opaque.beauty[i])) << "under the blob, row " << y;
  }
  // The glass refracts the ground and its shadow where the ground-less
  // render saw the floor of the map: with the same samples, its pixels
  // change where paths through it look down.
  int covered = 0, changed = 0;
  for (std::size_t i = 0; i < paths.pixelCount(); ++i) {
    if (bare.beauty[i].a < 1.0f) continue;
    ++covered;
    changed += std::abs(luminance3(paths.beauty[i]) - luminance3(bare.beauty[i])) > 0.01f * luminance3(bare.beauty[i]);
  }
  std::printf("glass blob: %d of %d pixels see the ground\n", changed, covered);
  EXPECT_GT(changed, covered / 4);
  for (int x = 0; x < w; ++x) EXPECT_EQ(paths.beauty[paths.index(x, 0)], bare.beauty[bare.index(x, 0)]) << x;
}

}  // namespace
}  // namespace facet

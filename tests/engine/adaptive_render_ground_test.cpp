// The adaptive renderer with the preview's ground (scenes/ground_plane.h), on
// the GPU backend, a blob over it under light from overhead: the ground
// right under the blob is darker than the background by a real margin, the
// far ground is the background within noise, the sky and the blob's own
// pixels are exactly the ground-less render's.
#include "engine/adaptive_render.h"

#include <gtest/gtest.h>

#include "tests/support/ground_blob.h"

namespace facet {
namespace {

float luminance3(const glm::vec4& p) { return 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b; }

TEST(GroundPlane, CatchesTheBlobsShadowAndIsOtherwiseUnseen) {
  const scene::Scene model = testing::blobOverGround();
  const scene::GroundScenes ground = scene::groundScenes(model);
  // Two rounds for every tile, with or without the ground: the same samples.
  // No time limit (the default), so that load cannot cut either render short.
  AdaptiveSettings settings;
  settings.maxSpp = 8;
  settings.noiseThreshold = 1e-4;
  settings.tileSize = 8;
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

// Adaptive sampling on the CPU reference: it stops where every tile's
// estimated error is below the threshold unless a cap stops it first, and
// says which; a noisier estimator takes more samples than a smoother one.
#include "engine/adaptive_render.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <memory>

#include "engine/camera/camera.h"
#include "scenes/studio_environment.h"
#include "tests/support/blob_scene.h"

namespace facet {
namespace {

scene::Scene studioBlob(scene::IblMethod method, int pairs) {
  scene::Scene s = testing::blobUnder(testing::lambertian(0.7),
                                      std::make_shared<const scene::EnvironmentMap>(scene::studioEnvironmentMap()), 32);
  s.environment->method = method;
  s.environment->samples = pairs;
  return s;
}

AdaptiveSettings settings(double threshold, int maxSpp) {
  AdaptiveSettings s;
  s.noiseThreshold = threshold;
  s.maxSpp = maxSpp;
  s.tileSize = 8;
  return s;
}

TEST(AdaptiveRender, StopsWithEveryTileBelowTheThreshold) {
  Renderer renderer;
  const AdaptiveReport r =
      renderAdaptive(renderer, studioBlob(scene::IblMethod::Sampled, 2), Backend::Cpu, settings(0.03, 4096));
  ASSERT_EQ(r.stop, AdaptiveStop::Converged);
  ASSERT_EQ(r.errors.size(), 16u);
  for (std::size_t t = 0; t < r.errors.size(); ++t) {
    EXPECT_LE(r.errors[t], 0.03) << "tile " << t;
    EXPECT_GE(r.tileSpp[t], 4 * AdaptiveSettings{}.minRounds)
        << "tile " << t << " stopped before its spread was trusted";
  }
  EXPECT_LE(r.maxError, 0.03);
  EXPECT_EQ(r.image.width, 32);
  EXPECT_GT(*std::max_element(r.tileSpp.begin(), r.tileSpp.end()),
            *std::min_element(r.tileSpp.begin(), r.tileSpp.end()))
      << "the background's tiles stop before the surface's";
  std::uint64_t samples = 0;
  for (int spp : r.tileSpp) samples += std::uint64_t(spp) * 64;
  EXPECT_LE(samples, r.samples) << "rounds render the active tiles' bounds";
  EXPECT_DOUBLE_EQ(r.sppMean, double(samples) / (32.0 * 32.0));
}

TEST(AdaptiveRender, ANoisierEstimatorTakesMoreSamples) {
  Renderer renderer;
  const AdaptiveReport smooth =
      renderAdaptive(renderer, studioBlob(scene::IblMethod::Prefiltered, 1), Backend::Cpu, settings(0.04, 4096));
  const AdaptiveReport noisy =
      renderAdaptive(renderer, studioBlob(scene::IblMethod::Sampled, 1), Backend::Cpu, settings(0.04, 4096));
  ASSERT_EQ(smooth.stop, AdaptiveStop::Converged);
  ASSERT_EQ(noisy.stop, AdaptiveStop::Converged);
  EXPECT_GT(noisy.samples, 2 * smooth.samples);
}

TEST(AdaptiveRender, ASampleCapStopsItAndSaysSo) {
  Renderer renderer;
  const AdaptiveReport r =
      renderAdaptive(renderer, studioBlob(scene::IblMethod::Sampled, 1), Backend::Cpu, settings(1e-5, 16));
  EXPECT_EQ(r.stop, AdaptiveStop::SampleCap);
  for (int spp : r.tileSpp) EXPECT_LE(spp, 16);
  EXPECT_GT(r.maxError, 1e-5);
  EXPECT_EQ(r.rounds, 4);
}

TEST(AdaptiveRender, HasNoTimeLimitUnlessGivenOne) {
  // The other tests render with the default, so their rounds depend on the settings alone.
  EXPECT_EQ(AdaptiveSettings{}.timeLimitSeconds, kNoTimeLimit);
}

TEST(AdaptiveRender, ATimeLimitStopsItAndSaysSo) {
  Renderer renderer;
  AdaptiveSettings s = settings(1e-5, 65536);
  s.timeLimitSeconds = 1e-6;  // spent by the first round however idle the machine: load only makes it later
  const AdaptiveReport r = renderAdaptive(renderer, studioBlob(scene::IblMethod::Sampled, 1), Backend::Cpu, s);
  EXPECT_EQ(r.stop, AdaptiveStop::TimeCap);
  EXPECT_EQ(r.rounds, 1);
}

TEST(AdaptiveRender, RefusesSettingsOutsideTheRules) {
  Renderer renderer;
  const scene::Scene s = studioBlob(scene::IblMethod::Prefiltered, 1);
  EXPECT_THROW(renderAdaptive(renderer, s, Backend::Cpu, settings(0.0, 64)), std::invalid_argument);
  EXPECT_THROW(renderAdaptive(renderer, s, Backend::Cpu, settings(0.1, 4)), std::invalid_argument);
  AdaptiveSettings noTime = settings(0.1, 64);
  noTime.timeLimitSeconds = -1;
  EXPECT_THROW(renderAdaptive(renderer, s, Backend::Cpu, noTime), std::invalid_argument);
}

// A farm's tile is a crop: its tiles start at its corner, so a crop on the
// whole image's tile lines takes each tile's rounds, samples and pixels.
TEST(AdaptiveRender, ACropOnTheTilesLinesRendersTheWholeImagesPixels) {
  Renderer renderer;
  const scene::Scene s = studioBlob(scene::IblMethod::Sampled, 1);
  const AdaptiveReport whole = renderAdaptive(renderer, s, Backend::Cpu, settings(0.05, 4096));
  const PixelRect crop{8, 16, 24, 32};
  const AdaptiveReport part = renderAdaptive(renderer, s, Backend::Cpu, settings(0.05, 4096), {crop, 0});
  ASSERT_EQ(part.image.width, 16);
  ASSERT_EQ(part.image.height, 16);
  EXPECT_EQ(part.render.window, crop);
  ASSERT_EQ(part.tileSpp.size(), 4u);
  EXPECT_EQ(part.tileSpp[0], whole.tileSpp[2 * 4 + 1]);
  EXPECT_EQ(part.tileSpp[3], whole.tileSpp[3 * 4 + 2]);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const std::size_t in = part.image.index(x, y), of = whole.image.index(x + crop.x0, y + crop.y0);
      ASSERT_EQ(part.image.beauty[in], whole.image.beauty[of]) << x << "," << y;
      ASSERT_EQ(part.image.faceId[in], whole.image.faceId[of]) << x << "," << y;
    }
  EXPECT_THROW(renderAdaptive(renderer, s, Backend::Cpu, settings(0.03, 64), {PixelRect{0, 0, 40, 8}, 0}),
               std::invalid_argument);
}

// renderPicture: one pass where the scene states its samples, adaptive
// rounds to the scene's own threshold and cap where it states them; where
// it leaves them to choose, one pass of 16 where no light is sampled at
// random, else adaptive rounds, and the report says why.
TEST(AdaptiveRender, APictureSamplesAsTheSceneSays) {
  Renderer renderer;
  scene::Scene s = studioBlob(scene::IblMethod::Sampled, 1);
  s.render.samplesPerPixel = 4;
  AdaptiveReport rounds;
  const RenderReport pass = renderPicture(renderer, s, Backend::Cpu, {}, {}, kNoTimeLimit, &rounds);
  EXPECT_EQ(rounds.rounds, 0);
  s.render.sampling = scene::Sampling::Adaptive;
  s.render.noiseThreshold = 0.2;
  s.render.maxSamplesPerPixel = 64;
  const RenderReport adaptive = renderPicture(renderer, s, Backend::Cpu, {}, {}, kNoTimeLimit, &rounds);
  EXPECT_EQ(rounds.noiseThreshold, 0.2);
  EXPECT_EQ(rounds.rounds, AdaptiveSettings{}.minRounds) << "so loose a threshold is met once the spread is trusted";
  EXPECT_EQ(adaptive.primaryRays, 4 * pass.primaryRays) << "the report counts every round's rays";
  EXPECT_EQ(adaptive.image.beauty.size(), 32u * 32u);
  EXPECT_TRUE(rounds.image.beauty.empty()) << "the image is the report's";
  EXPECT_EQ(adaptive.samplesPerPixel, 0);
  EXPECT_TRUE(adaptive.samplingNote.empty()) << "stated, not chosen";

  s.render.sampling = scene::Sampling::Chosen;
  AdaptiveReport chosenRounds;
  const RenderReport random = renderPicture(renderer, s, Backend::Cpu, {}, {}, kNoTimeLimit, &chosenRounds);
  EXPECT_EQ(random.samplesPerPixel, 0);
  EXPECT_EQ(chosenRounds.rounds, AdaptiveSettings{}.minRounds);
  EXPECT_EQ(random.samplingNote, "the environment is sampled at random");

  scene::Scene exact = studioBlob(scene::IblMethod::Prefiltered, 1);
  exact.render.sampling = scene::Sampling::Chosen;
  const RenderReport pass16 = renderPicture(renderer, exact, Backend::Cpu);
  EXPECT_EQ(pass16.samplesPerPixel, 16);
  EXPECT_EQ(pass16.samplingNote, "no light is sampled at random");
  exact.render.sampling = scene::Sampling::OnePass;
  exact.render.samplesPerPixel = 16;
  EXPECT_EQ(renderPicture(renderer, exact, Backend::Cpu).image.beauty, pass16.image.beauty)
      << "the chosen pass is the stated one";
}

TEST(AdaptiveRender, EachRoundsPixelsSeeWhatTheImagesPixelsSee) {
  scene::Scene s = studioBlob(scene::IblMethod::Sampled, 1);
  s.render.width = 48;
  s.render.height = 20;
  s.camera.verticalFovDegrees = 35;
  const rules::f64::CameraFrame image = camera::cameraFrame(s.camera, 48, 20);
  for (int round : {0, 1, 63, 70, 300}) {
    const RoundFrame r = roundFrame(s, round);
    EXPECT_EQ(r.dx, round % 64);
    EXPECT_EQ(r.dy, round / 64);
    const int w = r.scene.render.width, h = r.scene.render.height;
    EXPECT_EQ(w, 48 + 2 * r.dx);
    EXPECT_EQ(h, 20 + 2 * r.dy);
    const rules::f64::CameraFrame larger = camera::cameraFrame(r.scene.camera, w, h);
    for (const glm::dvec2 p : {glm::dvec2(0.25, 0.5), glm::dvec2(47.9, 19.1), glm::dvec2(13.5, 2.75)}) {
      const glm::dvec3 expected = rules::f64::camera_ray_direction(image, p.x, p.y, 48, 20);
      const glm::dvec3 seen = rules::f64::camera_ray_direction(larger, p.x + r.dx, p.y + r.dy, w, h);
      EXPECT_LT(glm::length(seen - expected), 1e-12) << "round " << round << " at " << p.x << "," << p.y;
    }
  }
}

TEST(AdaptiveRender, RoundsDrawIndependentSamples) {
  // Two rounds of the same pixels at the same spp differ (other random
  // numbers) but agree on average (the same estimator).
  Renderer renderer;
  scene::Scene s = studioBlob(scene::IblMethod::Sampled, 1);
  s.render.samplesPerPixel = 4;
  const PixelRect window{8, 8, 24, 24};
  const RoundFrame second = roundFrame(s, 5);
  const Image a = renderer.render(s, Backend::Cpu, {}, {window}).image;
  const Image b =
      renderer
          .render(
              second.scene, Backend::Cpu, {},
              {PixelRect{window.x0 + second.dx, window.y0 + second.dy, window.x1 + second.dx, window.y1 + second.dy}})
          .image;
  double meanA = 0, meanB = 0, differ = 0;
  for (std::size_t i = 0; i < a.beauty.size(); ++i) {
    meanA += luminance(a.beauty[i]) / double(a.beauty.size());
    meanB += luminance(b.beauty[i]) / double(a.beauty.size());
    differ += a.beauty[i] != b.beauty[i] ? 1.0 : 0.0;
    EXPECT_EQ(a.beauty[i].a > 0, b.beauty[i].a > 0) << "the same surface at pixel " << i;
  }
  EXPECT_GT(differ, 0.5 * double(a.beauty.size())) << "most pixels drew other samples";
  EXPECT_NEAR(meanA, meanB, 0.05 * meanA);
}

}  // namespace
}  // namespace facet

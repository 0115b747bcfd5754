// Adaptive sampling on the CPU reference: it stops where every tile's
// estimated error is below the threshold unless a cap stops it first, and
// says which; a noisier estimator takes more samples than a smoother one.
#include "engine/adaptive_render.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <memory>

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
  s.timeLimitSeconds = 600;
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

TEST(AdaptiveRender, ATimeLimitStopsItAndSaysSo) {
  Renderer renderer;
  AdaptiveSettings s = settings(1e-5, 65536);
  s.timeLimitSeconds = 1e-6;  // spent by the first round
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

// Where the old target lands in the shifted camera's image, by the pinhole
// of rules/camera/camera.h.
glm::dvec2 targetPixel(const scene::Camera& old, const scene::Camera& c, int w, int h) {
  const glm::dvec3 f = glm::normalize(c.target - c.eye), r = glm::normalize(glm::cross(f, c.up)), u = glm::cross(r, f);
  const glm::dvec3 d = old.target - c.eye;
  const double t = std::tan(glm::radians(c.verticalFovDegrees) / 2);
  const double sx = glm::dot(d, r) / glm::dot(d, f), sy = glm::dot(d, u) / glm::dot(d, f);
  return {(sx / (t * w / h) + 1) * w / 2, (1 - sy / t) * h / 2};
}

TEST(AdaptiveRender, AShiftedCameraMovesTheImageByTheShift) {
  scene::Camera c;
  c.eye = {1, 2, 5};
  c.target = {0, 0.5, 0};
  const glm::dvec2 centre = targetPixel(c, shiftedCamera(c, 64, 32, 0, 0), 64, 32);
  EXPECT_NEAR(centre.x, 32, 1e-9);
  EXPECT_NEAR(centre.y, 16, 1e-9);
  const glm::dvec2 moved = targetPixel(c, shiftedCamera(c, 64, 32, 0.4, -0.3), 64, 32);
  // A turn moves the image by the shift to first order in it.
  EXPECT_NEAR(moved.x, 32 - 0.4, 5e-3) << "the scene moves against the camera";
  EXPECT_NEAR(moved.y, 16 + 0.3, 5e-3);
}

}  // namespace
}  // namespace facet

#include "engine/adaptive_render.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/image/catcher_composite.h"
#include "scenes/light_transport.h"
#include "scenes/scene_geometry.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void checkSettings(const AdaptiveSettings& s) {
  if (!validNoiseThreshold(s.noiseThreshold))
    throw std::invalid_argument("noise threshold " + std::to_string(s.noiseThreshold) + ": " + kNoiseThresholdRule);
  if (!validMaxSpp(s.maxSpp)) throw std::invalid_argument("max spp " + std::to_string(s.maxSpp) + ": " + kMaxSppRule);
  if (s.timeLimitSeconds != kNoTimeLimit && !validTimeLimit(s.timeLimitSeconds))
    throw std::invalid_argument("time limit " + std::to_string(s.timeLimitSeconds) + ": " + kTimeLimitRule);
  if (s.roundSpp < 1 || !scene::isSquare(s.roundSpp) || s.minRounds < 2 || s.tileSize < 1)
    throw std::invalid_argument("adaptive rounds need a square spp, two rounds or more and a positive tile size");
}

// The smallest rectangle holding every tile listed.
PixelRect boundsOf(const TileGrid& grid, const std::vector<int>& tiles) {
  PixelRect bounds = grid.tile(tiles.front());
  for (int t : tiles) {
    const PixelRect r = grid.tile(t);
    bounds = {std::min(bounds.x0, r.x0), std::min(bounds.y0, r.y0), std::max(bounds.x1, r.x1),
              std::max(bounds.y1, r.y1)};
  }
  return bounds;
}

// Round `round` of `scene` over `window` of the full image.
RenderReport renderRound(Renderer& renderer, const scene::Scene& scene, int round, const PixelRect& window,
                         Backend backend, unsigned threads) {
  RoundFrame frame = roundFrame(scene, round);
  if (frame.scene.environment) frame.scene.environment->seed = scene.environment->seed + std::uint32_t(round);
  const PixelRect crop{window.x0 + frame.dx, window.y0 + frame.dy, window.x1 + frame.dx, window.y1 + frame.dy};
  return renderer.render(frame.scene, backend, {}, {crop, threads});
}

// The ground's two renders, summed over the rounds each pixel took: the
// same rounds, camera samples and random numbers as the model's, so that
// the ratio of the sums keeps H <= B sample by sample (catchShadows).
struct GroundSums {
  std::vector<glm::vec4> holdout, ground;
  std::vector<int> rounds;
};

// Round `round` of the ground's scenes over `window`, added to the pixels
// of the `active` tiles.
void addGroundRound(Renderer& renderer, const scene::GroundScenes& scenes, int round, const PixelRect& window,
                    const TileGrid& grid, const std::vector<int>& active, Backend backend, unsigned threads,
                    GroundSums& sums) {
  const Image holdout = renderRound(renderer, scenes.holdout, round, window, backend, threads).image;
  const Image alone = renderRound(renderer, scenes.ground, round, window, backend, threads).image;
  for (int t : active) {
    const PixelRect tile = grid.tile(t);
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x) {
        const std::size_t at = std::size_t(y) * std::size_t(grid.width) + std::size_t(x);
        const std::size_t in = holdout.index(x - window.x0, y - window.y0);
        sums.holdout[at] += holdout.beauty[in];
        sums.ground[at] += alone.beauty[in];
        ++sums.rounds[at];
      }
  }
}

// The model's mean over its rounds with the ground's shadow caught from the
// ground's means.
std::vector<glm::vec4> caughtBeauty(int width, int height, const std::vector<glm::vec4>& model,
                                    const GroundSums& sums) {
  std::vector<glm::vec4> holdout(model.size()), ground(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) {
    holdout[i] = sums.holdout[i] / float(sums.rounds[i]);
    ground[i] = sums.ground[i] / float(sums.rounds[i]);
  }
  return catchShadows(width, height, model, holdout, ground);
}

scene::Scene withRoundSpp(scene::Scene scene, int spp) {
  scene.render.samplesPerPixel = spp;
  return scene;
}

}  // namespace

const char* toString(AdaptiveStop stop) {
  switch (stop) {
    case AdaptiveStop::Converged:
      return "converged";
    case AdaptiveStop::SampleCap:
      return "sample cap";
    case AdaptiveStop::TimeCap:
      return "time limit";
  }
  return "?";
}

RoundFrame roundFrame(const scene::Scene& scene, int round) {
  RoundFrame frame{scene, round % 64, round / 64};
  frame.scene.render.width += 2 * frame.dx;
  frame.scene.render.height += 2 * frame.dy;
  // tan(fov'/2) / H' = tan(fov/2) / H: rules/camera/camera.h then gives
  // pixel (x + dx, y + dy) of the larger image the ray of pixel (x, y).
  const double tanHalf = std::tan(glm::radians(scene.camera.verticalFovDegrees) / 2.0);
  frame.scene.camera.verticalFovDegrees =
      glm::degrees(2.0 * std::atan(tanHalf * frame.scene.render.height / scene.render.height));
  if (double(frame.scene.render.width) * frame.scene.render.height > 4294967295.0)
    throw std::invalid_argument("adaptive round " + std::to_string(round) + ": the image has too many pixels");
  return frame;
}

AdaptiveReport renderAdaptive(Renderer& renderer, const scene::Scene& scene, Backend backend,
                              const AdaptiveSettings& settings, unsigned threads, const scene::GroundScenes* ground) {
  checkSettings(settings);
  const Clock::time_point start = Clock::now();
  const int width = scene.render.width, height = scene.render.height;
  // Chosen once for every round, not per round (scenes/light_transport.h).
  std::optional<scene::LightTransport> transport;
  if (scene::leavesLightTransportUnsaid(scene))
    transport = scene::chooseLightTransport(scene, scene::buildGeometry(scene));
  const scene::Scene round =
      withRoundSpp(transport ? scene::withLightTransport(scene, *transport) : scene, settings.roundSpp);
  std::optional<scene::GroundScenes> groundRound;
  if (ground)
    groundRound = scene::GroundScenes{withRoundSpp(ground->holdout, settings.roundSpp),
                                      withRoundSpp(ground->ground, settings.roundSpp)};
  SampleRounds rounds(width, height, settings.tileSize);
  const TileGrid& grid = rounds.grid();
  AdaptiveReport report;
  report.tileSpp.assign(std::size_t(grid.count()), 0);
  report.errors.assign(std::size_t(grid.count()), 0.0);
  std::vector<int> active(std::size_t(grid.count()));
  for (int t = 0; t < grid.count(); ++t) active[std::size_t(t)] = t;
  GroundSums groundSums;
  if (groundRound) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    groundSums = {std::vector<glm::vec4>(pixels, glm::vec4(0)), std::vector<glm::vec4>(pixels, glm::vec4(0)),
                  std::vector<int>(pixels, 0)};
  }

  while (!active.empty()) {
    // Each round is an independent randomization of the same estimator:
    // its pixels' indices, which key the camera's scrambled nets and the
    // lighting's random numbers (rules/camera/camera_samples.h,
    // rules/sampling/random.h), and its seed are its own, so the rounds'
    // spread is an unbiased estimate of their variance (L'Ecuyer & Lemieux
    // 2002). The first is the scene itself: its centre samples give the AOVs.
    const PixelRect window = boundsOf(grid, active);
    RenderReport rendered = renderRound(renderer, round, report.rounds, window, backend, threads);
    // The ground takes the first rounds only: its shadow, averaged over a
    // window of pixels, is smooth by then, and a tile the model keeps going
    // (a bright edge, a noisy lobe) does not make it pay three renders a round.
    if (groundRound && report.rounds < settings.minRounds)
      addGroundRound(renderer, *groundRound, report.rounds, window, grid, active, backend, threads, groundSums);
    rounds.add(rendered.image, window, active);
    report.samples += std::uint64_t(settings.roundSpp) * window.pixelCount();
    if (report.rounds++ == 0) {
      report.first = std::move(rendered);
      if (transport) {
        report.first.lightTransport = *transport;
        report.first.warnings.insert(report.first.warnings.end(), transport->warnings.begin(),
                                     transport->warnings.end());
      }
    }

    std::vector<int> next;
    bool capped = false;
    for (int t : active) {
      report.tileSpp[std::size_t(t)] += settings.roundSpp;
      const double error = rounds.error(t);
      report.errors[std::size_t(t)] = error;
      if (rounds.rounds(t) >= settings.minRounds && error <= settings.noiseThreshold) continue;
      if (report.tileSpp[std::size_t(t)] + settings.roundSpp > settings.maxSpp) {
        capped = true;
        continue;
      }
      next.push_back(t);
    }
    if (capped) report.stop = AdaptiveStop::SampleCap;
    active = std::move(next);
    if (!active.empty() && secondsSince(start) >= settings.timeLimitSeconds) {
      report.stop = AdaptiveStop::TimeCap;
      break;
    }
  }
  report.image = std::move(report.first.image);
  if (report.image.width != width || report.image.height != height)
    throw std::logic_error("the first adaptive round must cover the whole image");
  report.image.beauty = groundRound ? caughtBeauty(width, height, rounds.beauty(), groundSums) : rounds.beauty();
  report.maxError = *std::max_element(report.errors.begin(), report.errors.end());
  for (int t = 0; t < grid.count(); ++t)
    report.sppMean += double(report.tileSpp[std::size_t(t)]) * double(grid.tile(t).pixelCount());
  report.sppMean /= double(grid.width) * double(grid.height);
  report.seconds = secondsSince(start);
  return report;
}

}  // namespace facet

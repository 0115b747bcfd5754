#include "engine/adaptive_render.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rules/rules.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void checkSettings(const AdaptiveSettings& s) {
  if (!validNoiseThreshold(s.noiseThreshold))
    throw std::invalid_argument("noise threshold " + std::to_string(s.noiseThreshold) + ": " + kNoiseThresholdRule);
  if (!validMaxSpp(s.maxSpp)) throw std::invalid_argument("max spp " + std::to_string(s.maxSpp) + ": " + kMaxSppRule);
  if (!validTimeLimit(s.timeLimitSeconds))
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

scene::Camera shiftedCamera(const scene::Camera& camera, int width, int height, double dx, double dy) {
  // The direction through image point (w/2 + dx, h/2 + dy) of
  // rules/camera/camera.h's pinhole becomes the new forward.
  const glm::dvec3 toTarget = camera.target - camera.eye;
  const glm::dvec3 forward = glm::normalize(toTarget);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(glm::radians(camera.verticalFovDegrees) / 2.0);
  const double sx = 2.0 * dx / width * tanHalf * double(width) / double(height), sy = -2.0 * dy / height * tanHalf;
  scene::Camera shifted = camera;
  shifted.target = camera.eye + glm::length(toTarget) * glm::normalize(forward + sx * right + sy * up);
  return shifted;
}

AdaptiveReport renderAdaptive(Renderer& renderer, const scene::Scene& scene, Backend backend,
                              const AdaptiveSettings& settings, unsigned threads) {
  checkSettings(settings);
  const Clock::time_point start = Clock::now();
  const int width = scene.render.width, height = scene.render.height;
  scene::Scene round = scene;
  round.render.samplesPerPixel = settings.roundSpp;
  const double strata = std::sqrt(double(settings.roundSpp));
  SampleRounds rounds(width, height, settings.tileSize);
  const TileGrid& grid = rounds.grid();
  AdaptiveReport report;
  report.tileSpp.assign(std::size_t(grid.count()), 0);
  report.errors.assign(std::size_t(grid.count()), 0.0);
  std::vector<int> active(std::size_t(grid.count()));
  for (int t = 0; t < grid.count(); ++t) active[std::size_t(t)] = t;

  while (!active.empty()) {
    // Each round is an independent randomization of the same estimator:
    // its lighting by its seed, its camera samples by a shift uniform over
    // one stratum of its net, so the rounds' spread is an unbiased estimate
    // of their variance (L'Ecuyer & Lemieux 2002). The first is unshifted:
    // its centre samples give the AOVs.
    const auto r = std::uint32_t(report.rounds);
    const double dx = r == 0 ? 0.0 : (rules::f64::sample_uniform(r, 0x5eedu, 0u) - 0.5) / strata;
    const double dy = r == 0 ? 0.0 : (rules::f64::sample_uniform(r, 0x5eedu, 1u) - 0.5) / strata;
    round.camera = shiftedCamera(scene.camera, width, height, dx, dy);
    if (round.environment) round.environment->seed = scene.environment->seed + r;
    const PixelRect window = boundsOf(grid, active);
    RenderReport rendered = renderer.render(round, backend, {}, {window, threads});
    rounds.add(rendered.image, window, active);
    report.samples += std::uint64_t(settings.roundSpp) * window.pixelCount();
    if (report.rounds++ == 0) report.first = std::move(rendered);

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
  report.image.beauty = rounds.beauty();
  report.maxError = *std::max_element(report.errors.begin(), report.errors.end());
  report.seconds = secondsSince(start);
  return report;
}

}  // namespace facet

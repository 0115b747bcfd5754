#include "engine/adaptive_render.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/image/catcher_composite.h"
#include "scenes/light_transport.h"
#include "scenes/sampling_choice.h"
#include "scenes/scene_geometry.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void checkSettings(const AdaptiveSettings& s) {
  if (!scene::validNoiseThreshold(s.noiseThreshold))
    throw std::invalid_argument("noise threshold " + std::to_string(s.noiseThreshold) + ": " +
                                scene::kNoiseThresholdRule);
  if (!scene::validMaxSpp(s.maxSpp))
    throw std::invalid_argument("max spp " + std::to_string(s.maxSpp) + ": " + scene::kMaxSppRule);
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

// `rect` moved by (dx, dy).
PixelRect moved(const PixelRect& rect, int dx, int dy) {
  return {rect.x0 + dx, rect.y0 + dy, rect.x1 + dx, rect.y1 + dy};
}

// A scene and its geometry, built once for all its rounds: a round's frame
// widens the image by whole pixels of the same size, which changes neither
// the objects nor their refinement (scenes/scene_geometry.h).
struct RoundScene {
  scene::Scene scene;
  std::shared_ptr<const scene::SceneGeometry> geometry;
};

// The geometry of `scene`: `given` where there is one, else built, and the
// time that took added to `milliseconds`.
std::shared_ptr<const scene::SceneGeometry> geometryOf(const scene::Scene& scene, double& milliseconds,
                                                       std::shared_ptr<const scene::SceneGeometry> given = nullptr) {
  if (given) return given;
  const Clock::time_point start = Clock::now();
  auto built = std::make_shared<const scene::SceneGeometry>(scene::buildGeometry(scene));
  milliseconds += 1000.0 * secondsSince(start);
  return built;
}

RoundScene withGeometry(scene::Scene scene, double& milliseconds) {
  std::shared_ptr<const scene::SceneGeometry> geometry = geometryOf(scene, milliseconds);
  return {std::move(scene), std::move(geometry)};
}

// Round `round` of `scene` over `window` of the full image.
RenderReport renderRound(Renderer& renderer, const RoundScene& scene, int round, const PixelRect& window,
                         Backend backend, unsigned threads) {
  RoundFrame frame = roundFrame(scene.scene, round);
  if (frame.scene.environment) frame.scene.environment->seed = scene.scene.environment->seed + std::uint32_t(round);
  return renderer.render(frame.scene, backend, {}, {moved(window, frame.dx, frame.dy), threads, scene.geometry});
}

// `stage`'s time added to the same stage's in `stages`, or a stage of its own.
void addStageTime(std::vector<StageTime>& stages, const StageTime& stage) {
  auto same = std::find_if(stages.begin(), stages.end(), [&](const StageTime& s) { return s.stage == stage.stage; });
  if (same == stages.end())
    stages.push_back(stage);
  else
    same->milliseconds += stage.milliseconds;
}

// The ground's two scenes (scene::GroundScenes) and their geometry, built
// by the first round that renders them: rounds a sheet's cells share need
// none.
struct GroundRoundScenes {
  RoundScene holdout, ground;
};

// The ground's two renders, summed over the rounds each pixel took: the
// same rounds, camera samples and random numbers as the model's, so that
// the ratio of the sums keeps H <= B sample by sample (catchShadows).
struct GroundSums {
  std::vector<glm::vec4> holdout, ground;
  std::vector<int> rounds;
};

// Round `round` of the ground's scenes over `window`: the one `kept` holds
// for that round and window, else rendered (its stages added to `stages`,
// the scenes' geometry built where it is not yet, its time added to
// `geometryMilliseconds`) and kept.
const GroundRound& groundRound(Renderer& renderer, GroundRoundScenes& scenes, int round, const PixelRect& window,
                               Backend backend, unsigned threads, std::vector<StageTime>& stages,
                               double& geometryMilliseconds, std::vector<GroundRound>& kept) {
  if (std::size_t(round) < kept.size() && kept[std::size_t(round)].window == window) return kept[std::size_t(round)];
  for (RoundScene* scene : {&scenes.holdout, &scenes.ground})
    scene->geometry = geometryOf(scene->scene, geometryMilliseconds, scene->geometry);
  RenderReport holdout = renderRound(renderer, scenes.holdout, round, window, backend, threads);
  RenderReport ground = renderRound(renderer, scenes.ground, round, window, backend, threads);
  for (const RenderReport* render : {&holdout, &ground})
    for (const StageTime& stage : render->stages) addStageTime(stages, stage);
  kept.resize(std::max(kept.size(), std::size_t(round) + 1));
  return kept[std::size_t(round)] = {window, std::move(holdout.image), std::move(ground.image)};
}

// A round of the ground's renders, added to the pixels of the `active` tiles.
void addGroundRound(const GroundRound& round, const TileGrid& grid, const std::vector<int>& active, GroundSums& sums) {
  const Image& holdout = round.holdout;
  const Image& alone = round.ground;
  const PixelRect& window = round.window;
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

// What a later round cost, added to the first's report.
void addRoundCost(RenderReport& total, const RenderReport& round) {
  for (const StageTime& stage : round.stages) addStageTime(total.stages, stage);
  total.primaryRays += round.primaryRays;
  total.shadowRays += round.shadowRays;
  if (total.raysPerBounce.size() < round.raysPerBounce.size()) total.raysPerBounce.resize(round.raysPerBounce.size());
  for (std::size_t bounce = 0; bounce < round.raysPerBounce.size(); ++bounce) {
    total.raysPerBounce[bounce].rays += round.raysPerBounce[bounce].rays;
    total.raysPerBounce[bounce].hits += round.raysPerBounce[bounce].hits;
    total.raysPerBounce[bounce].shadowRays += round.raysPerBounce[bounce].shadowRays;
  }
  total.newtonFallbacks += round.newtonFallbacks;
  total.cells += round.cells;
  total.warnings.insert(total.warnings.end(), round.warnings.begin(), round.warnings.end());
}

scene::Scene withRoundSpp(scene::Scene scene, int spp) {
  scene.render.samplesPerPixel = spp;
  return scene;
}

}  // namespace

std::pair<int, int> tileSppRange(const AdaptiveReport& report) {
  const auto [fewest, most] = std::minmax_element(report.tileSpp.begin(), report.tileSpp.end());
  return {*fewest, *most};
}

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

namespace {

// The tiles of `active` that go on after a round: not those whose spread is
// trusted and below the threshold, nor those the next round would take past
// the cap (which `report` says stopped them). Each tile's samples and error
// so far are noted in `report`.
std::vector<int> tilesGoingOn(const std::vector<int>& active, const SampleRounds& rounds,
                              const AdaptiveSettings& settings, AdaptiveReport& report) {
  std::vector<int> next;
  for (int t : active) {
    report.tileSpp[std::size_t(t)] += settings.roundSpp;
    const double error = rounds.error(t);
    report.errors[std::size_t(t)] = error;
    if (rounds.rounds(t) >= settings.minRounds && error <= settings.noiseThreshold) continue;
    if (report.tileSpp[std::size_t(t)] + settings.roundSpp > settings.maxSpp) {
      report.stop = AdaptiveStop::SampleCap;
      continue;
    }
    next.push_back(t);
  }
  return next;
}

// The ground's part of an adaptive render: its two scenes, the rounds they
// rendered (kept in `shared`, else its own), their sums and their stages.
struct GroundState {
  GroundRoundScenes scenes;
  SharedGroundRenders* shared = nullptr;
  std::vector<GroundRound> own;
  GroundSums sums;
  std::vector<StageTime> stages;

  std::vector<GroundRound>& kept() { return shared ? shared->rounds : own; }
};

// The ground's part of the rounds of `model` (its scene with the light
// transport chosen), whose scene takes the catcher where paths run: they see
// the ground they stand on, and the ground receives what they send onto it
// (docs/preview-stage.md, "The ground in the paths"). Without paths the
// ground's renders hold nothing of the model's materials, and `shared`'s
// rounds serve.
GroundState groundStateOf(const scene::GroundScenes& ground, RoundScene& model, int roundSpp, std::size_t pixels,
                          SharedGroundRenders* shared, double& geometryMilliseconds) {
  const bool paths = model.scene.render.bounces > 0;
  GroundState state{
      {{withRoundSpp(paths ? scene::holdoutWithPaths(ground, model.scene) : ground.holdout, roundSpp), nullptr},
       {withRoundSpp(ground.ground, roundSpp), nullptr}},
      paths ? nullptr : shared,
      {},
      {std::vector<glm::vec4>(pixels, glm::vec4(0)), std::vector<glm::vec4>(pixels, glm::vec4(0)),
       std::vector<int>(pixels, 0)},
      {}};
  if (paths) model = withGeometry(scene::withShadowCatcher(std::move(model.scene), ground), geometryMilliseconds);
  return state;
}

}  // namespace

AdaptiveReport renderAdaptive(Renderer& renderer, const scene::Scene& scene, Backend backend,
                              const AdaptiveSettings& settings, const RenderOptions& options,
                              const std::function<void(double)>& progress, const scene::GroundScenes* ground,
                              SharedGroundRenders* sharedGround) {
  checkSettings(settings);
  const Clock::time_point start = Clock::now();
  const PixelRect area = options.crop.value_or(PixelRect::whole(scene.render.width, scene.render.height));
  if (area.empty() || !area.inside(scene.render.width, scene.render.height))
    throw std::invalid_argument("crop " + area.text() + ": expected a non-empty rectangle inside the image");
  if (ground && !(area == PixelRect::whole(scene.render.width, scene.render.height)))
    throw std::invalid_argument("crop " + area.text() + ": the shadow-catching ground renders the whole image");
  const int width = area.width(), height = area.height();
  const unsigned threads = options.threads;
  // Chosen once for every round, not per round (scenes/light_transport.h).
  double geometryMilliseconds = 0;
  RoundScene model{scene, geometryOf(scene, geometryMilliseconds, options.geometry)};
  std::optional<scene::LightTransport> transport;
  if (scene::leavesLightTransportUnsaid(scene)) transport = scene::chooseLightTransport(scene, *model.geometry);
  model.scene = withRoundSpp(transport ? scene::withLightTransport(scene, *transport) : scene, settings.roundSpp);
  std::optional<GroundState> groundState;
  if (ground)
    groundState = groundStateOf(*ground, model, settings.roundSpp, std::size_t(width) * std::size_t(height),
                                sharedGround, geometryMilliseconds);
  SampleRounds rounds(width, height, settings.tileSize);
  const TileGrid& grid = rounds.grid();
  AdaptiveReport report;
  report.noiseThreshold = settings.noiseThreshold;
  report.tileSpp.assign(std::size_t(grid.count()), 0);
  report.errors.assign(std::size_t(grid.count()), 0.0);
  std::vector<int> active(std::size_t(grid.count()));
  for (int t = 0; t < grid.count(); ++t) active[std::size_t(t)] = t;

  while (!active.empty()) {
    // Each round is an independent randomization of the same estimator:
    // its pixels' indices, which key the camera's scrambled nets and the
    // lighting's random numbers (rules/camera/camera_samples.h,
    // rules/sampling/random.h), and its seed are its own, so the rounds'
    // spread is an unbiased estimate of their variance (L'Ecuyer & Lemieux
    // 2002). The first is the scene itself: its centre samples give the AOVs.
    // The grid's pixels of the round, and the same pixels of the full image.
    const PixelRect window = boundsOf(grid, active);
    RenderReport rendered =
        renderRound(renderer, model, report.rounds, moved(window, area.x0, area.y0), backend, threads);
    // The ground takes the first rounds only: its shadow, averaged over a
    // window of pixels, is smooth by then, and a tile the model keeps going
    // (a bright edge, a noisy lobe) does not make it pay three renders a round.
    if (groundState && report.rounds < settings.minRounds)
      addGroundRound(groundRound(renderer, groundState->scenes, report.rounds, window, backend, threads,
                                 groundState->stages, geometryMilliseconds, groundState->kept()),
                     grid, active, groundState->sums);
    rounds.add(rendered.image, window, active);
    report.samples += std::uint64_t(settings.roundSpp) * window.pixelCount();
    if (report.rounds > 0) {
      addRoundCost(report.render, rendered);
    } else {
      report.render = std::move(rendered);
      if (transport) {
        report.render.lightTransport = *transport;
        report.render.warnings.insert(report.render.warnings.end(), transport->warnings.begin(),
                                      transport->warnings.end());
      }
    }
    ++report.rounds;

    active = tilesGoingOn(active, rounds, settings, report);
    if (progress) progress(1.0 - double(active.size()) / double(grid.count()));
    if (!active.empty() && secondsSince(start) >= settings.timeLimitSeconds) {
      report.stop = AdaptiveStop::TimeCap;
      break;
    }
  }
  if (groundState)
    for (const StageTime& stage : groundState->stages) addStageTime(report.render.stages, stage);
  addStageTime(report.render.stages, {Stage::RefineBvh, geometryMilliseconds});
  report.image = std::move(report.render.image);
  if (report.image.width != width || report.image.height != height)
    throw std::logic_error("the first adaptive round must cover the whole image or crop");
  report.image.beauty = groundState ? caughtBeauty(width, height, rounds.beauty(), groundState->sums) : rounds.beauty();
  report.maxError = *std::max_element(report.errors.begin(), report.errors.end());
  for (int t = 0; t < grid.count(); ++t)
    report.sppMean += double(report.tileSpp[std::size_t(t)]) * double(grid.tile(t).pixelCount());
  report.sppMean /= double(grid.width) * double(grid.height);
  report.seconds = secondsSince(start);
  return report;
}

RenderReport renderPicture(Renderer& renderer, const scene::Scene& scene, Backend backend,
                           const std::function<void(double)>& progress, const RenderOptions& options,
                           double timeLimitSeconds, AdaptiveReport* rounds) {
  scene::Scene sampled = scene;
  std::optional<scene::LightTransport> transport;
  std::string samplingNote;
  RenderOptions built = options;
  double geometryMilliseconds = 0;
  if (scene.render.sampling == scene::Sampling::Chosen) {
    // The choice rests on the light transport's: chosen once, here, for the
    // renders below, which take the geometry it was chosen on.
    if (scene::leavesLightTransportUnsaid(scene)) {
      built.geometry = geometryOf(scene, geometryMilliseconds, options.geometry);
      transport = scene::chooseLightTransport(scene, *built.geometry);
    }
    if (transport) sampled = scene::withLightTransport(scene, *transport);
    samplingNote = scene::chooseSampling(sampled);
  }
  RenderReport report;
  if (sampled.render.sampling == scene::Sampling::OnePass) {
    report = renderer.render(sampled, backend, progress, built);
  } else {
    AdaptiveReport adaptive =
        renderAdaptive(renderer, sampled, backend, adaptiveSettings(sampled.render, timeLimitSeconds), built, progress);
    report = std::move(adaptive.render);
    report.image = std::move(adaptive.image);
    report.samplesPerPixel = 0;
    if (rounds) *rounds = std::move(adaptive);
  }
  if (transport) report.lightTransport = *transport;
  addStageTime(report.stages, {Stage::RefineBvh, geometryMilliseconds});
  report.samplingNote = samplingNote;
  return report;
}

}  // namespace facet

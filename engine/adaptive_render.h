// Adaptive sampling over the renderer, host-side: rounds of samples, each
// with its own random numbers, until every tile's estimated noise is below
// a threshold or a sample or time cap is reached (docs/preview-stage.md,
// "Adaptive sampling"). The kernels are the renderer's own; only which
// pixels each round renders, and the random numbers they draw, changes.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "engine/image/sample_rounds.h"
#include "engine/renderer.h"
#include "scenes/ground_plane.h"

namespace facet {

// No time limit: the rounds, and with them the image, follow from the scene
// and the settings alone, however busy the machine is.
inline constexpr double kNoTimeLimit = std::numeric_limits<double>::infinity();

struct AdaptiveSettings {
  double noiseThreshold = scene::kDefaultNoiseThreshold;  // a tile's relative standard error (SampleRounds::error)
  int maxSpp = scene::kDefaultMaxSamplesPerPixel;         // camera samples per pixel at most
  double timeLimitSeconds = kNoTimeLimit;  // no round starts after this; the command line sets one
  int roundSpp = 4;                        // camera samples per pixel of each round (a square)
  int minRounds = 4;                       // before a tile's spread is trusted
  int tileSize = 16;
};

// The time limit's rule, for the command line and the APIs alike; the
// others are the scene's (scenes/scene.h).
inline constexpr const char* kTimeLimitRule = "expected a number of seconds in (0, 86400]";
inline bool validTimeLimit(double seconds) { return seconds > 0.0 && seconds <= 86400.0; }

// A scene's own stopping rules (RenderSettings), with a time limit.
inline AdaptiveSettings adaptiveSettings(const scene::RenderSettings& render, double timeLimitSeconds = kNoTimeLimit) {
  AdaptiveSettings settings;
  settings.noiseThreshold = render.noiseThreshold;
  settings.maxSpp = render.maxSamplesPerPixel;
  settings.timeLimitSeconds = timeLimitSeconds;
  return settings;
}

enum class AdaptiveStop { Converged, SampleCap, TimeCap };
const char* toString(AdaptiveStop stop);

struct AdaptiveReport {
  // The beauty: each pixel's mean over its rounds; the AOVs of the first
  // round, which passes through each pixel's centre.
  Image image;
  // The first round's device, geometry and light transport; every round's
  // rays, and the stages of every render a round made (the ground's too).
  RenderReport render;
  AdaptiveStop stop = AdaptiveStop::Converged;
  int rounds = 0;              // renders made
  std::uint64_t samples = 0;   // camera samples rendered, finished tiles inside a round's crop too
  double sppMean = 0;          // camera samples per pixel kept, over the image
  std::vector<double> errors;  // per tile, when it stopped
  double noiseThreshold = 0;   // the settings' threshold
  std::vector<int> tileSpp;    // per tile: camera samples per pixel taken
  double maxError = 0;         // the largest of `errors`
  double seconds = 0;          // wall clock of every round
};

// The fewest and the most camera samples per pixel a tile took.
std::pair<int, int> tileSppRange(const AdaptiveReport& report);

// One round of a ground's two renders (scenes/ground_plane.h): the holdout
// and the ground alone, over `window` of the full image.
struct GroundRound {
  PixelRect window;
  Image holdout, ground;
};

// The ground's rounds of pictures without paths, which hold nothing of the
// model's materials: pictures of one model in several materials, with the
// same ground, camera, light and settings (a contact sheet's cells), render
// them once.
struct SharedGroundRenders {
  std::vector<GroundRound> rounds;  // by round number
};

// Renders `scene` (its size; its spp and seed are the rounds') by rounds,
// telling `progress` after each the share of tiles finished. With
// `options.crop`, over that part of the image only: its tiles start at the
// crop's corner, so a crop on the tiles' lines renders the whole image's
// pixels there. With `ground` (scenes/ground_plane.h, of the same camera
// and size, the whole image), each round renders its two scenes over the
// same pixels too; the rounds stop on the model's noise, and the beauty is
// the shadow catcher's composite of the three renders' means
// (engine/image/catcher_composite.h). A picture without paths takes the
// ground's rounds `sharedGround` holds, and keeps there those it renders.
// Throws std::invalid_argument for settings that break the rules above, or
// a crop outside the image.
AdaptiveReport renderAdaptive(Renderer& renderer, const scene::Scene& scene, Backend backend,
                              const AdaptiveSettings& settings, const RenderOptions& options = {},
                              const std::function<void(double)>& progress = {},
                              const scene::GroundScenes* ground = nullptr, SharedGroundRenders* sharedGround = nullptr);

// A picture of `scene` as its sampling says (RenderSettings::sampling): one
// pass of its samples per pixel, or adaptive rounds to its noise threshold
// and sample cap, which `rounds` receives where given (the image moved into
// the result's); where the scene leaves it to choose, as
// scenes/sampling_choice.h chooses, the report saying what and why. The
// command line and the APIs render by it.
RenderReport renderPicture(Renderer& renderer, const scene::Scene& scene, Backend backend,
                           const std::function<void(double)>& progress = {}, const RenderOptions& options = {},
                           double timeLimitSeconds = kNoTimeLimit, AdaptiveReport* rounds = nullptr);

// Round `round`'s scene and where its pixels lie: the image inside a larger
// one, (a, b) = (round % 64, round / 64) pixels wider on the left and
// right, taller above and below, its field of view widened to keep the
// pixels' size, so that every pixel sees what it saw but has another index
// in the full image, and with it other random numbers (docs/preview-stage.md,
// "Adaptive sampling"). Round 0 is the scene itself.
struct RoundFrame {
  scene::Scene scene;
  int dx = 0, dy = 0;  // the image's pixel (x, y) is the round's (x + dx, y + dy)
};
RoundFrame roundFrame(const scene::Scene& scene, int round);

}  // namespace facet

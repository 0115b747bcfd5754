// Adaptive sampling over the renderer, host-side: rounds of samples, each
// with its own random numbers, until every tile's estimated noise is below
// a threshold or a sample or time cap is reached (docs/preview-stage.md,
// "Adaptive sampling"). The kernels are the renderer's own; only which
// pixels each round renders, and the random numbers they draw, changes.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "engine/image/sample_rounds.h"
#include "engine/renderer.h"
#include "scenes/ground_plane.h"

namespace facet {

// No time limit: the rounds, and with them the image, follow from the scene
// and the settings alone, however busy the machine is.
inline constexpr double kNoTimeLimit = std::numeric_limits<double>::infinity();

struct AdaptiveSettings {
  double noiseThreshold = 0.02;            // a tile's relative standard error (SampleRounds::error)
  int maxSpp = 256;                        // camera samples per pixel at most
  double timeLimitSeconds = kNoTimeLimit;  // no round starts after this; the command line sets one
  int roundSpp = 4;                        // camera samples per pixel of each round (a square)
  int minRounds = 4;                       // before a tile's spread is trusted
  int tileSize = 16;
};

// The settings' rules, for the command line and the APIs alike.
inline constexpr const char* kNoiseThresholdRule = "expected a number in (0, 1]";
inline constexpr const char* kMaxSppRule = "expected a whole number of samples in [8, 65536] (two rounds of 4)";
inline constexpr const char* kTimeLimitRule = "expected a number of seconds in (0, 86400]";
inline bool validNoiseThreshold(double t) { return t > 0.0 && t <= 1.0; }
inline bool validMaxSpp(long long spp) { return spp >= 8 && spp <= 65536; }
inline bool validTimeLimit(double seconds) { return seconds > 0.0 && seconds <= 86400.0; }

enum class AdaptiveStop { Converged, SampleCap, TimeCap };
const char* toString(AdaptiveStop stop);

struct AdaptiveReport {
  // The beauty: each pixel's mean over its rounds; the AOVs of the first
  // round, which passes through each pixel's centre.
  Image image;
  RenderReport first;  // the first round's report: device, stages, geometry
  AdaptiveStop stop = AdaptiveStop::Converged;
  int rounds = 0;              // renders made
  std::uint64_t samples = 0;   // camera samples rendered, finished tiles inside a round's crop too
  double sppMean = 0;          // camera samples per pixel kept, over the image
  std::vector<double> errors;  // per tile, when it stopped
  std::vector<int> tileSpp;    // per tile: camera samples per pixel taken
  double maxError = 0;         // the largest of `errors`
  double seconds = 0;          // wall clock of every round
};

// Renders `scene` (its size; its spp and seed are the rounds') by rounds.
// With `ground` (scenes/ground_plane.h, of the same camera and size), each
// round renders its two scenes over the same pixels too; the rounds stop on
// the model's noise, and the beauty is the shadow catcher's composite of the
// three renders' means (engine/image/catcher_composite.h).
// Throws std::invalid_argument for settings that break the rules above.
AdaptiveReport renderAdaptive(Renderer& renderer, const scene::Scene& scene, Backend backend,
                              const AdaptiveSettings& settings, unsigned threads = 0,
                              const scene::GroundScenes* ground = nullptr);

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

// How much light transport a render traces (docs/rendering.md, "Light
// transport chosen by the scene"). Where the scene leaves the bounces unsaid,
// paths run with Cycles' default limits wherever a continuation can meet a
// surface, and direct light alone where none can; where they run, an
// environment whose method is unsaid is sampled with its shadow rays, and
// one whose samples are unsaid takes kChosenEnvironmentPairs. Stated
// settings always win: paths that cannot continue are still cast as none.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::scene {

// Cycles' default bounce limits (Blender 3.4: Max Bounces, Light Paths).
inline constexpr int kChosenBounces = 12;
inline constexpr int kChosenDiffuseBounces = 4;
inline constexpr int kChosenGlossyBounces = 4;
inline constexpr int kChosenTransmissionBounces = 12;
// The environment's pairs per camera sample where facet chooses paths and
// nothing said the samples: the split between camera samples and pairs
// that reached a given error soonest on the bouncing scenes
// (BENCHMARKS.md, "Environment pairs chosen with the paths").
inline constexpr int kChosenEnvironmentPairs = 2;

struct LightTransport {
  int bounces = 0;
  int diffuseBounces = -1;
  int glossyBounces = -1;
  int transmissionBounces = -1;
  bool samplesEnvironment = false;  // the environment switched to sampled, occlusion on
  int environmentPairs = 0;         // chosen pairs per camera sample; 0: as the scene has them
  // What was chosen and why, for the summary line ("paths: 12 bounces ...:
  // 'teacup' is concave"); empty where the scene stated it all and nothing
  // was dropped.
  std::string note;
  // A transmissive material that no path passes through, a volume of glass
  // that is not closed.
  std::vector<std::string> warnings;
};

LightTransport chooseLightTransport(const Scene& scene, const SceneGeometry& geometry);

// Leaves nothing to choose: one pass of the samples per pixel as they are
// (1 where unsaid), the bounces as they are (0 where unsaid, the course's
// local model), and the environment's method as it is unless stated
// bounces need it sampled. For comparisons whose subject is the backends,
// not the picture (parity).
void leaveNothingToChoose(Scene& scene);

// The scene file at `path`, nothing left to choose: for measurements
// of one method or setting (facet bench, facet ibl-chart), which render
// what they set and nothing chosen.
Scene loadStatedScene(const std::filesystem::path& path);

// The seed of the random numbers the beauty's Monte Carlo estimate draws
// (sampled or filtered lighting, paths), whose renders seeds apart are
// judged by a paired t-test (docs/parity.md); none where the beauty is no
// such estimate (prefiltered lighting without paths, or no environment,
// whose paths draw fixed numbers).
std::optional<std::uint32_t> estimateSeed(const Scene& scene);

// Whether the scene leaves anything to choose.
bool leavesLightTransportUnsaid(const Scene& scene);

// `scene` with `transport` applied and nothing left to choose, for renders
// of one scene repeated (adaptive rounds) that choose once.
Scene withLightTransport(Scene scene, const LightTransport& transport);

// Whether rendering `scene` with `transport` differs from rendering it as it is.
bool changesScene(const LightTransport& transport, const Scene& scene);
void applyLightTransport(const LightTransport& transport, Scene& scene);

}  // namespace facet::scene

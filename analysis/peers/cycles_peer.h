// Blender Cycles as a peer of `facet bench`: finding Blender, describing a
// facet scene in the terms of tools/blender/cycles_scene.py, running it and
// reading its times. Both Cycles sections (analysis/bench/cycles.cpp,
// cycles_paths.cpp) render through this.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "scenes/scene.h"

namespace facet::peers {

// Cycles' equirectangular map looks down Blender's +x at its centre, which
// is facet's map turned by 270 degrees about +y.
constexpr double kCyclesMapRotationDegrees = 270;
// Catmull-Clark levels of the cages Blender renders, vertices on the limit surface.
constexpr int kCyclesSubdivisionLevels = 7;

// FACET_BLENDER, else `blender` on PATH; nothing when neither exists.
std::optional<std::filesystem::path> findBlender();

// Blender and tools/blender/cycles_scene.py.
struct CyclesPeer {
  std::filesystem::path blender, script;
};

// Threads Cycles runs on: as many as lavapipe's (LP_NUM_THREADS), else the machine's.
unsigned cyclesThreads();

// Writes `directory`/scene.json and a world-space OBJ per object for
// cycles_scene.py, and returns the description's path. Throws where a
// material has no counterpart there (a Cycles metal, Lambert or glass; see
// the script) or the scene has no environment.
std::filesystem::path describeForCycles(const scene::Scene& scene, const std::filesystem::path& directory);

struct CyclesRenders {
  std::vector<int> samples;  // timed, `repeats` times each, seed 0
  int repeats = 1;
  int converged = 0;  // > 0: two untimed renders at this many samples, seeds 1 and 2
};

// Runs Blender on the description; its output goes to `directory`/blender.log.
void renderInCycles(const std::filesystem::path& blender, const std::filesystem::path& script,
                    const std::filesystem::path& description, const CyclesRenders& renders,
                    const std::filesystem::path& directory);

// Per sample count, the median of Cycles' timed render calls (seconds);
// throws naming the file where a count of `samples` has no time.
std::map<int, double> readCyclesTimes(const std::filesystem::path& csv, const std::vector<int>& samples);

// Cycles' image at `exr`, which holds beauty alone: its surfaces are
// facet's, so the `reference`'s AOVs (coverage, depth, normals) stand for
// its own. Throws where it is not the reference's size or holds a pixel that
// is not finite: a render that failed is never measured.
Image readCyclesImage(const std::filesystem::path& exr, const Image& reference);

}  // namespace facet::peers

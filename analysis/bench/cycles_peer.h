// Blender Cycles as a peer of `facet bench`: finding Blender, describing a
// facet scene in the terms of tools/blender/cycles_scene.py, and running it.
// Both Cycles sections (cycles.cpp, cycles_paths.cpp) render through this.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <functional>

#include "analysis/report.h"
#include "engine/renderer.h"
#include "scenes/scene.h"

namespace facet::analysis::bench {

// Cycles' equirectangular map looks down Blender's +x at its centre, which
// is facet's map turned by 270 degrees about +y.
constexpr double kCyclesMapRotationDegrees = 270;
// Catmull-Clark levels of the cages Blender renders, vertices on the limit surface.
constexpr int kCyclesSubdivisionLevels = 7;

// FACET_BLENDER, else `blender` on PATH; nothing when neither exists.
std::optional<std::filesystem::path> findBlender();

// Blender and tools/blender/cycles_scene.py under `root`; where either is
// missing, prints "SECTION: skipped: why", says so in the report and returns nothing.
struct CyclesPeer {
  std::filesystem::path blender, script;
};
std::optional<CyclesPeer> findCyclesPeer(const std::filesystem::path& root, const std::string& section, Report& report);

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

// A render's time and error on a curve of increasing samples.
struct Point {
  std::string curve;
  int samples = 0;  // Cycles: samples per pixel; facet: the curve's own count
  double milliseconds = 0;
  double relativeRmse = 0;
};

// The time at which a curve, ordered by N, first reaches `error`:
// interpolated linearly in log time against log error between its
// neighbouring points; nothing when it never does.
std::optional<double> timeToError(const std::vector<Point>& curve, double error);

// One facet point: the median of `repeats` runs of `render`'s tracing
// stages, its image's error against `reference`; printed as it is measured.
Point timedPoint(const std::string& curve, int samples, int repeats, const std::function<RenderReport()>& render,
                 const Image& reference);

// The fastest facet curve's time to `target`'s error (a Cycles point), as a sentence.
std::string verdict(const std::vector<std::vector<Point>>& curves, const Point& target);

// Per sample count, the median of Cycles' timed render calls (seconds).
std::map<int, double> readCyclesTimes(const std::filesystem::path& csv);

}  // namespace facet::analysis::bench

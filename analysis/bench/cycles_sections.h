// What the two Cycles sections of `facet bench` (cycles.cpp, cycles_paths.cpp)
// share around the peer (analysis/peers/cycles_peer.h): finding it or saying
// why the section is skipped, and the time-against-error curves they compare.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/peers/cycles_peer.h"
#include "analysis/report.h"
#include "engine/renderer.h"

namespace facet::analysis::bench {

// The peer under `root`; where Blender or its script is missing, prints
// "SECTION: skipped: why", says so in the report and returns nothing.
std::optional<peers::CyclesPeer> findCyclesPeer(const std::filesystem::path& root, const std::string& section,
                                                Report& report);

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

}  // namespace facet::analysis::bench

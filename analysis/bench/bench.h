// facet bench: every method against time and error, where each fails, how
// each scales, and the peers beside them (README, "Speed against
// accuracy"). Each section lives in its own file and adds its CSVs, charts
// and prose to one Markdown report.
#pragma once

#include <filesystem>
#include <string>

#include "analysis/image_compare.h"
#include "analysis/report.h"
#include "analysis/timing.h"

namespace facet::analysis::bench {

struct BenchOptions {
  std::filesystem::path output;  // everything is written below it
  std::filesystem::path root;    // the folder holding scenes/ (share/facet or the source tree)
  bool quick = false;            // the CI smoke run: tiny sizes, few points, one repetition
  int repeats = 5;               // timed runs per point; the median is reported
};

// The sections, in the order `facet bench` runs them.
void runPareto(Renderer& renderer, const BenchOptions& options, Report& report);
void runStability(Renderer& renderer, const BenchOptions& options, Report& report);
void runScaling(Renderer& renderer, const BenchOptions& options, Report& report);
// Needs Blender (FACET_BLENDER, else `blender` on PATH); skipped with a note without it.
void runCycles(Renderer& renderer, const BenchOptions& options, Report& report);
void runCyclesPaths(Renderer& renderer, const BenchOptions& options, Report& report);

}  // namespace facet::analysis::bench

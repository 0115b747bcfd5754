// Error against time for the three image-based lighting methods, sampled at
// N = 1, 4, 16, ... pairs, filtered at N = 1, 4, 16, 64 and the prefiltered
// split sum, per roughness, on each environment: a CSV, a gnuplot chart and
// previews (`facet ibl-chart`); and the camera samples' convergence on the
// first environment (antialiasing_slope.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/renderer.h"
#include "scenes/scene.h"

namespace facet::analysis {

struct IblChartSettings {
  std::filesystem::path output;                     // ibl_chart.csv, .svg, .png and the previews
  scene::Scene base;                                // geometry, materials and size; its lights are removed
  std::vector<std::filesystem::path> environments;  // one chart panel each
  std::vector<double> alphas;                       // set on every material in turn
  std::vector<int> sampleCounts;                    // N of the sampled method, ascending
  std::vector<int> antialiasingSamples;             // samples per pixel of the camera samples' curve, powers of 4
  int repeats = 3;                                  // timed runs per point; the median is charted
  Backend backend = Backend::Gpu;
};

// The reference is sampled with this many times the largest N, so that its
// own noise is half the largest N's and the curve's tail stays meaningful.
constexpr int kIblReferenceFactor = 4;

// The filtered method's range of N (docs/rendering.md, "Filtered importance sampling").
constexpr int kMaxFilteredChartSamples = 64;

void writeIblChart(Renderer& renderer, const IblChartSettings& settings);

}  // namespace facet::analysis

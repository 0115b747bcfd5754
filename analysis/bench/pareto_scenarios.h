// What the Pareto section measures: the scenes, the knob settings swept on
// each, the error the chart's y axis shows, and the sizes that keep the
// section within its share of `facet bench`'s time.
#pragma once

#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "scenes/scene.h"

namespace facet::analysis::bench::pareto {

// What the chart's y axis measures: rendered radiance, or where the rays
// hit (the torture cages, where Embree, which only casts, joins in).
enum class ErrorAxis { Beauty, Depth };

// One knob setting of one method. `knob` is empty for the prefiltered split
// sum, which has none.
struct Setting {
  std::string method;  // exact, tessellated, sampled, prefiltered
  std::string knob;    // epsilon, k, N, rate
  double value = 0;

  std::string label() const {
    if (knob.empty()) return method;
    const std::string shown = knob == "epsilon" ? "ε" : knob;
    return method + " " + shown + "=" + cell(value);
  }
};

struct Scenario {
  std::string name;
  std::string description;
  scene::Scene scene;
  ErrorAxis axis = ErrorAxis::Beauty;
  std::vector<Setting> settings;
  bool embreePeer = false;
  int referenceSamples = 0;  // sampled IBL pairs of the reference; 0: the scene's own environment method
};

// Chosen so the default run stays within its share of `facet bench`'s time
// on 2 lavapipe cores.
struct Sizes {
  int previewWidth, previewHeight;
  int cageSize;
  int iblWidth, iblHeight;
  std::vector<std::string> cages;
  std::vector<double> tolerances;
  std::vector<int> tessellationRates;
  std::vector<int> iblSamples;
  int referenceSamples;
  std::vector<int> embreeRates;
};

Sizes sizesFor(bool quick);

// The y value of the chart: relative RMSE of the beauty, or mean relative
// depth error (the maximum is set by single silhouette pixels).
double chartedError(const ImageError& e, ErrorAxis axis);

std::string axisName(ErrorAxis axis);

// A point is good enough below this error; the report shows the fastest such
// render. Depth is held to a tighter bar: 1% of the depth is far more than a
// pixel's worth of surface on these cages.
double goodEnough(ErrorAxis axis);

// Log axes cannot show 0: such errors are drawn here (said on the chart).
constexpr double kChartFloor = 1e-12;

// The smallest ε the GPU honours, as a fraction of the scene's diagonal:
// 2^-20 (8 float ulps) of the largest coordinate of the scene and the eye
// (docs/rendering.md, "The GPU path").
double gpuToleranceFloor(const scene::Scene& scene);

std::vector<Scenario> scenarios(const BenchOptions& options, const Sizes& sizes);

}  // namespace facet::analysis::bench::pareto

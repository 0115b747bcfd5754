// Times read off renders: medians of repeated runs and the stage sums the
// analyses chart.
#pragma once

#include <functional>
#include <vector>

#include "engine/renderer.h"

namespace facet::analysis {

double median(std::vector<double> values);

// Runs `run` (which returns milliseconds) `repeats` times and returns the median.
double medianMilliseconds(int repeats, const std::function<double()>& run);

// The cost of casting and shading: every stage but refinement and the
// environment's preparation (sampling tables, prefiltering or its cache).
double traceMilliseconds(const RenderReport& report);
double preparationMilliseconds(const RenderReport& report);

}  // namespace facet::analysis

// The flags of adaptive sampling, alike for `facet render` and `facet
// preview` (docs/rendering.md, "Converged by default"): each value checked
// against its rule (engine/adaptive_render.h), or std::invalid_argument
// naming the flag.
#pragma once

namespace facet::cli {

double checkedNoiseThreshold(double threshold);  // --noise-threshold
int checkedMaxSpp(long long spp);                // --max-spp
double checkedTimeLimit(double seconds);         // --time-limit

}  // namespace facet::cli

// A scene's environment, made ready for either backend: the rotation as a
// cosine and sine, and what its method needs — the luminance distribution
// (sampled) or the prefiltered maps, SH irradiance and one DFG table per
// (D, G) pair of the scene's materials (prefiltered). Only what the method
// uses is built.
#pragma once

#include <functional>
#include <vector>

#include "engine/ibl/environment_distribution.h"
#include "engine/ibl/prefiltered_environment.h"
#include "scenes/scene.h"

namespace facet::ibl {

struct EnvironmentLighting {
  const scene::Environment* environment = nullptr;
  double cosRotation = 1;
  double sinRotation = 0;
  EnvironmentDistribution distribution;  // sampled
  PrefilteredEnvironment prefiltered;    // prefiltered
  std::vector<int> dfgTable;             // per scene material: index into prefiltered.dfg
};

// `prefilter` builds the prefiltered data (on the CPU or the GPU, through
// the cache); it is called only for the prefiltered method.
using PrefilterBuilder = std::function<PrefilteredEnvironment(const scene::EnvironmentMap&, const ModelPairs&)>;

// The scene must have an environment.
EnvironmentLighting prepareEnvironmentLighting(const scene::Scene& scene, const PrefilterBuilder& prefilter);

}  // namespace facet::ibl

// A scene's environment, made ready for either backend: the rotation as a
// cosine and sine, and what its method needs — the luminance distribution
// (sampled), the prefiltered maps, SH irradiance and one DFG table per
// (D, G) pair of the scene's materials (prefiltered), or the mip chain and,
// on maps with a small bright source, the distribution (filtered). Only what
// the method uses is built.
#pragma once

#include <functional>
#include <vector>

#include "engine/ibl/environment_distribution.h"
#include "engine/ibl/environment_mip_chain.h"
#include "engine/ibl/prefiltered_environment.h"
#include "scenes/scene.h"

namespace facet::ibl {

struct EnvironmentLighting {
  const scene::Environment* environment = nullptr;
  double cosRotation = 1;
  double sinRotation = 0;
  EnvironmentDistribution distribution;  // sampled; filtered with environmentSamples
  PrefilteredEnvironment prefiltered;    // prefiltered
  std::vector<int> dfgTable;             // per scene material: index into prefiltered.dfg
  int coatDfgTable = -1;                 // the clear coat's (GGX, correlated Smith) table, where a material has one
  std::vector<MipLevel> mipChain;        // filtered
  bool environmentSamples = false;       // filtered: pairs add the environment technique (filtered_environment.h)
  std::vector<MipLevel> pdfChain;        // filtered with environmentSamples: the density's chain, in all 3 channels
};

// The filtered method's rule for the environment technique, from the map's
// brightest texel and its mean radiance (luminance, solid-angle weighted).
bool filteredUsesEnvironmentSamples(const scene::EnvironmentMap& map);

// `prefilter` builds the prefiltered data (on the CPU or the GPU, through
// the cache); it is called only for the prefiltered method.
using PrefilterBuilder = std::function<PrefilteredEnvironment(const scene::EnvironmentMap&, const ModelPairs&)>;

// The scene must have an environment.
EnvironmentLighting prepareEnvironmentLighting(const scene::Scene& scene, const PrefilterBuilder& prefilter);

}  // namespace facet::ibl

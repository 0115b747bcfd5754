// The map's solid-angle-weighted 2 x 2-box mip chain, in double: what the
// prefilter reads its GGX samples from, and what the filtered method reads
// each BRDF sample from at the level its density asks for (Krivanek &
// Colbert 2008; docs/rendering.md, "Filtered importance sampling").
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

#include "scenes/environment_map.h"

namespace facet::ibl {

struct MipLevel {
  int width = 0;
  int height = 0;
  std::vector<double> rgb;  // row-major, 3 per texel, the map's layout
};

// Level 0 is the map; the levels of sourceChainSizes (prefilter_steps.h) follow.
std::vector<MipLevel> mipChain(const scene::EnvironmentMap& map);

// Bilinear within the two levels around `lod` (clamped to the chain), linear between them.
glm::dvec3 mipChainRadiance(const std::vector<MipLevel>& chain, const glm::dvec2& uv, double lod);

}  // namespace facet::ibl

// Luminance importance sampling of an environment map, for the sampled
// method (docs/rendering.md, "Sampled"): a texel with probability
// proportional to the largest luminance of its 3 x 3 neighbourhood times its
// solid angle, then uniformly inside it, so that
//   pdf(w) = P(texel) / solid angle(texel).
// A black map falls back to weights by solid angle alone. Texels come from
// an alias table (Walker 1977, Vose 1991): O(1) and loop-free, as lavapipe's
// limit on an invocation's loop iterations asks. Built in double; the GPU
// receives the same tables, probabilities rounded to float.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

#include "scenes/environment_map.h"

namespace facet::ibl {

struct EnvironmentDistribution {
  int width = 0;
  int height = 0;
  std::vector<double> keep;          // per texel: probability of keeping it once picked
  std::vector<std::uint32_t> alias;  // per texel: the texel taken otherwise
  std::vector<double> texelPdf;      // per texel, density per unit solid angle
};

EnvironmentDistribution buildDistribution(const scene::EnvironmentMap& map);

struct EnvironmentSample {
  glm::dvec3 direction;  // in the map's frame
  double pdf = 0;        // per unit solid angle
};

// `texelBits`: 32 random bits that pick a texel (as the high word of
// bits x texel count, so that every texel of a map beyond 2^24 texels is
// reachable); u: numbers in [0, 1) for keep or alias and the position
// inside the texel.
EnvironmentSample sampleEnvironment(const EnvironmentDistribution& distribution, std::uint32_t texelBits,
                                    const glm::dvec3& u);

// Density of sampleEnvironment at `direction` (map frame).
double environmentPdf(const EnvironmentDistribution& distribution, const glm::dvec3& direction);

}  // namespace facet::ibl

// Luminance importance sampling of an environment map, for the sampled
// method. A texel is drawn with probability proportional to the largest
// luminance of its 3 x 3 neighbourhood (what a bilinear lookup inside it
// can reach) times its solid angle, then u and cos(theta) uniformly inside
// it, so the density per unit solid angle is constant over each texel:
//   pdf(w) = P(texel) / solid angle(texel).
// A black map falls back to weights by solid angle alone (uniform over the
// sphere), so the pdf stays a density wherever it is asked.
//
// Texels are drawn from an alias table (Walker 1977, Vose 1991): one
// uniform picks a texel, a second keeps it or takes its alias. That is O(1)
// and loop-free, which matters on lavapipe: it stops a shader invocation's
// loops after 65535 iterations in all, and a binary search per sample would
// reach that at a few thousand samples per pixel.
//
// Built in double; the GPU receives the same tables, probabilities rounded
// to float.
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

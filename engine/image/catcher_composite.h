// A shadow catcher's composite (docs/preview-stage.md, "The ground"): the
// model's own render over its background, the background darkened where a
// ground plane the model shadows is seen, by the ratio of the ground's
// radiance with the model to its radiance without it.
#pragma once

#include <glm/vec4.hpp>

#include <vector>

namespace facet {

// Where the ground's unshadowed radiance, averaged over the window below,
// is at most this, no light reaches it to be blocked: the pixel is left as
// the model's render has it.
inline constexpr float kCatcherRadianceFloor = 1e-6f;

// The ratio is summed over the ground in a (2 radius + 1)^2 window of
// pixels: the visibility of the environment is noisy per pixel and smooth
// over a few.
inline constexpr int kCatcherRadius = 2;

// Three renders of the same pixels (width x height, row by row), with the
// same camera samples and random numbers, RGB and alpha = coverage:
//   model    the model alone, as the picture shows it;
//   holdout  the model, black, and the ground, lit with shadow rays;
//   ground   the ground alone, lit the same way.
// Returns the model's render with the background behind the pixel's ground
// share scaled per channel by the shadow factor s in [0, 1]; alpha is the
// model's. Throws std::invalid_argument where the planes' sizes differ.
std::vector<glm::vec4> catchShadows(int width, int height, const std::vector<glm::vec4>& model,
                                    const std::vector<glm::vec4>& holdout, const std::vector<glm::vec4>& ground,
                                    int radius = kCatcherRadius);

}  // namespace facet

// The display encoding of linear radiance: the sRGB transfer function.
#pragma once

#include <glm/vec3.hpp>

namespace facet {

// The sRGB transfer function (IEC 61966-2-1), linear -> encoded.
double linearToSrgb(double linear);
glm::dvec3 linearToSrgb(glm::dvec3 linear);

}  // namespace facet

// Display encodings of linear radiance: the sRGB transfer function and the
// tone curve of the PNG preview.
#pragma once

#include <glm/vec3.hpp>

namespace facet {

// The sRGB transfer function (IEC 61966-2-1), linear -> encoded.
double linearToSrgb(double linear);
glm::dvec3 linearToSrgb(glm::dvec3 linear);

// The preview's tone curve: linear × exposureScale (2^stops), clipped to
// [0, 1], sRGB-encoded.
double previewToneCurve(float linear, float exposureScale);

}  // namespace facet

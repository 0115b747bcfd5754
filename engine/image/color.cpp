#include "engine/image/color.h"

#include <cmath>

namespace facet {

double linearToSrgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

glm::dvec3 linearToSrgb(glm::dvec3 linear) {
  return {linearToSrgb(linear.x), linearToSrgb(linear.y), linearToSrgb(linear.z)};
}

}  // namespace facet

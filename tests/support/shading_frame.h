// The frame the shading rules' tests evaluate in: the normal is +z and a
// direction is given by its polar and azimuthal angles about it.
#pragma once

#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace facet::testing {

inline constexpr double kPi = std::numbers::pi;
inline const glm::dvec3 kN(0, 0, 1);

// The unit direction at polar angle theta from kN and azimuth phi (radians).
inline glm::dvec3 direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace facet::testing

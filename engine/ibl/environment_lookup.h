// Texel reads and bilinear lookups in equirectangular RGB arrays (float maps
// and levels, double mip chains), in double: the CPU side of what the kernels
// do with environment_bilinear (rules/environment/environment_mapping.h).
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>

#include "rules/rules.h"

namespace facet::ibl {

template <class Real>
glm::dvec3 texelAt(const Real* rgb, int width, int x, int y) {
  const Real* p = rgb + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  return {p[0], p[1], p[2]};
}

template <class Real>
glm::dvec3 bilinearLookup(const Real* rgb, int width, int height, const glm::dvec2& uv) {
  const rules::f64::BilinearTaps t = rules::f64::environment_bilinear(uv, width, height);
  const glm::dvec3 top = glm::mix(texelAt(rgb, width, t.x0, t.y0), texelAt(rgb, width, t.x1, t.y0), t.fx);
  const glm::dvec3 bottom = glm::mix(texelAt(rgb, width, t.x0, t.y1), texelAt(rgb, width, t.x1, t.y1), t.fx);
  return glm::mix(top, bottom, t.fy);
}

}  // namespace facet::ibl

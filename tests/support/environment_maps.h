// Environment maps built in memory for the prefiltered-environment tests.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "rules/rules.h"
#include "scenes/environment_map.h"

namespace facet::ibl::testing {

// A width x height map holding radiance(direction at the texel's centre).
inline scene::EnvironmentMap mapOf(int width, int height, const std::function<glm::dvec3(glm::dvec3)>& radiance) {
  scene::EnvironmentMap map;
  map.width = width;
  map.height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 d = rules::f64::environment_direction(glm::dvec2((x + 0.5) / width, (y + 0.5) / height));
      const glm::dvec3 value = radiance(d);
      for (int channel = 0; channel < 3; ++channel) map.rgb.push_back(float(value[channel]));
    }
  return map;
}

// A smooth sky, brighter and bluer overhead, and a small sun 100 times as
// bright as the sky about 30 degrees above the horizon.
inline glm::dvec3 skyWithSun(const glm::dvec3& d) {
  const glm::dvec3 sky = glm::dvec3(0.4, 0.6, 1.0) * (1.2 + d.y) + glm::dvec3(0.2, 0.1, 0.0) * d.x;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.6, 0.5, -0.62));
  return glm::dot(d, sun) > 0.995 ? glm::dvec3(120.0, 100.0, 80.0) : sky;
}

// Integral over the map's texels (each piecewise constant) of
// radiance x weight(direction) d omega, each texel split into sub x sub
// cells of exact solid angle.
inline glm::dvec3 integrateOverTexels(const scene::EnvironmentMap& map, int sub,
                                      const std::function<double(glm::dvec3)>& weight, double* weightSum = nullptr) {
  namespace m = rules::f64;
  glm::dvec3 sum(0.0);
  double total = 0;
  const int columns = map.width * sub, rows = map.height * sub;
  for (int y = 0; y < rows; ++y) {
    const double c0 = std::cos(m::PI * y / rows), c1 = std::cos(m::PI * (y + 1) / rows);
    const double cellSolidAngle = 2 * m::PI / columns * (c0 - c1);
    for (int x = 0; x < columns; ++x) {
      const glm::dvec3 d = m::environment_direction_cos((x + 0.5) / columns, 0.5 * (c0 + c1));
      const double w = weight(d) * cellSolidAngle;
      sum += w * glm::dvec3(map.texel(x / sub, y / sub));
      total += w;
    }
  }
  if (weightSum) *weightSum = total;
  return sum;
}

inline double maxRelativeDifference(const glm::dvec3& a, const glm::dvec3& b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] - b[c]) / std::max(std::abs(b[c]), 1e-30));
  return worst;
}

}  // namespace facet::ibl::testing

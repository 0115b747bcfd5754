// The ceiling's geometry: the micro-grids facet traverses (k x k cells of
// each patch's limit surface, k the object's own dicing rate) as plain
// triangles.
#pragma once

#include <glm/vec3.hpp>

#include <limits>
#include <vector>

#include "scenes/scene_geometry.h"

namespace facet::benchmarks::ceiling {

// No hit, and the bounds of an empty box.
constexpr float kInf = std::numeric_limits<float>::infinity();

struct Triangle {
  glm::vec3 a, b, c;
};

// Each patch's (k+1)² limit points, two triangles per cell, relative to the eye.
std::vector<Triangle> dice(const facet::scene::SceneGeometry& geometry, glm::dvec3 eye);

}  // namespace facet::benchmarks::ceiling

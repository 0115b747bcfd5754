// The ceiling's CPU check: every triangle tested in double, so that a pixel
// the BVH4 kernels get wrong is the traversal's fault, not the test's.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

#include "benchmarks/ceiling/micro_grid_triangles.h"

namespace facet::benchmarks::ceiling {

// The nearest hit of the ray `o` + t `d` within (0, tMax), or the first
// found with `anyHit`; kInf for none.
double bruteForce(const std::vector<Triangle>& tris, glm::dvec3 o, glm::dvec3 d, double tMax, bool anyHit);

}  // namespace facet::benchmarks::ceiling

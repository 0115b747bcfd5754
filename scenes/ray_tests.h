// The two ray tests every ray caster over the scene's geometry takes: the
// CPU reference's intersectors (engine/cpu/intersect.cpp) and the scene's
// own queries (scenes/camera_medium.cpp). Rays are origin + t direction.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

#include "scenes/bezier_patch.h"

namespace facet::scene {

// Slab test of the ray against a box, restricted to [tMin, tMax].
inline bool rayHitsBox(const glm::dvec3& origin, const glm::dvec3& direction, const Aabb& box, double tMin,
                       double tMax) {
  for (int axis = 0; axis < 3; ++axis) {
    const double o = origin[axis], d = direction[axis];
    if (d == 0.0) {
      if (o < box.lo[axis] || o > box.hi[axis]) return false;
      continue;
    }
    double t0 = (box.lo[axis] - o) / d, t1 = (box.hi[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    tMin = std::max(tMin, t0);
    tMax = std::min(tMax, t1);
    if (tMin > tMax) return false;
  }
  return true;
}

// Möller and Trumbore 1997; t and the barycentric weights of b and c.
inline bool rayHitsTriangle(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
                            const glm::dvec3& b, const glm::dvec3& c, double& t, double& wb, double& wc) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return false;
  const double inverse = 1.0 / det;
  const glm::dvec3 q = origin - a;
  wb = glm::dot(q, p) * inverse;
  if (wb < 0.0 || wb > 1.0) return false;
  const glm::dvec3 r = glm::cross(q, e1);
  wc = glm::dot(direction, r) * inverse;
  if (wc < 0.0 || wb + wc > 1.0) return false;
  t = glm::dot(e2, r) * inverse;
  return true;
}

}  // namespace facet::scene

// The two ray tests every ray caster over the scene's geometry takes: the
// CPU reference's intersectors (engine/cpu/intersect.cpp) and the scene's
// own queries (scenes/camera_medium.cpp). Rays are origin + t direction.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

#include "rules/rules.h"
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

// The shared rule (rules/surface/ray_triangle.h), watertight along shared
// edges, for a ray of frame `shear` (rules::f64::ray_shear of its
// direction); t and the barycentric weights of b and c.
inline bool rayHitsTriangle(const rules::f64::RayShear& shear, const glm::dvec3& origin, const glm::dvec3& a,
                            const glm::dvec3& b, const glm::dvec3& c, double& t, double& wb, double& wc) {
  rules::f64::TriangleHit hit;
  if (!rules::f64::ray_hits_triangle(shear, origin, a, b, c, hit)) return false;
  t = hit.t;
  wb = hit.wb;
  wc = hit.wc;
  return true;
}

}  // namespace facet::scene

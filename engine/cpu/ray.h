#pragma once
// Rays and hits of the CPU reference. Everything is double precision.

#include <glm/vec3.hpp>

#include "rules/rules.h"

#include <cstdint>
#include <limits>

namespace facet::cpu {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};  // need not be unit; t is in units of |direction|
  // Hits at t < tMin are ignored. Rays leaving an opaque surface (shadow
  // and secondary rays) start off it by the offset with tMin the same, about
  // 1e-6 x the scene diagonal: a thousand times the exact method's default
  // tolerance, so the surface they leave is not found again (tested). A path
  // leaving a transmissive surface has tMin 0 and its crossing instead.
  double tMin = 0.0;
  double tMax = std::numeric_limits<double>::infinity();
  // Decides where a blended surface lets the ray through (pass_through_key,
  // rules/surface/cutout.h).
  std::uint32_t passThroughKey = 0;
  // A ray that leaves a transmissive surface of object `crossedObject`
  // passes over what its crossing says (rules/surface/crossing.h).
  int crossedObject = -1;
  rules::f64::SurfaceCrossing crossing = rules::f64::no_crossing();

  glm::dvec3 at(double t) const { return origin + t * direction; }
};

struct SurfaceHit {
  double t = 0.0;
  glm::dvec3 position{0.0};
  // Normals are oriented by the cage's winding (faces counter-clockwise
  // seen from outside give outward normals), never flipped towards the ray.
  // Unit normal of the geometry the ray actually hit: the limit surface for
  // exact intersection, the micro-triangle for tessellated intersection.
  glm::dvec3 geometricNormal{0.0};
  // Unit limit normal dP/du x dP/dv at (u, v), with the fallback described
  // in limit_normal.h where that cross product vanishes.
  glm::dvec3 shadingNormal{0.0};
  int patch = -1;  // SubdivisionSurface patch index (PatchRecord::sourcePatch)
  int ptexFace = -1;
  int coarseFace = -1;
  double u = 0.0;  // ptex face parameters
  double v = 0.0;
};

}  // namespace facet::cpu

#pragma once
// The shading normal of the limit surface, robust where dP/du x dP/dv
// vanishes (OpenSubdiv issues #947 and #1352). On our cages that happens at
// patch corners: where an infinitely sharp crease turns a corner, dP/du and
// dP/dv become parallel; at some end-cap corners both are zero. The limit
// normal approaching such a point from inside its patch is well defined, so
// we evaluate at points moved towards the patch centre by growing fractions
// (1e-7 .. 1e-3 of the way) and take the first that is well defined.

#include "scenes/subdivision_surface.h"

namespace facet::cpu {

// Unit normal at face parameters (u, v) of `patch`.
glm::dvec3 limitNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v);

// The shading normal at (u, v): where a mesh as authored carries normals,
// theirs interpolated (compute/shared/authored_normal.h), turned to the side
// of the surface's own normal `limit`; else `limit`.
glm::dvec3 shadingNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v,
                         const glm::dvec3& limit);

// The cross product is trusted when |du x dv| exceeds this fraction of
// |du| |dv| (the sine of the angle between them) and neither derivative is
// zero.
inline constexpr double kDegenerateSine = 1e-6;

}  // namespace facet::cpu

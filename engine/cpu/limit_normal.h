#pragma once
// The shading normal on the CPU reference: the limit normal with the
// fallback of rules/surface/limit_normal.h where dP/du x dP/dv vanishes,
// evaluated by OpenSubdiv's own patch evaluation; and a mesh's authored
// normals and tangents where it carries them.

#include "scenes/subdivision_surface.h"

namespace facet::cpu {

// Unit normal at face parameters (u, v) of `patch`.
glm::dvec3 limitNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v);

// The shading normal at (u, v): where a mesh as authored carries normals,
// theirs interpolated (rules/surface/authored_normal.h), turned to the side
// of the surface's own normal `limit`; else `limit`.
glm::dvec3 shadingNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v,
                         const glm::dvec3& limit);

// The mesh's tangent at (u, v) where a mesh as authored carries tangents
// (rules/surface/tangent.h's mesh_tangent); zero, w included, elsewhere.
glm::dvec4 meshTangent(const scene::SubdivisionSurface& surface, int patch, double u, double v);

}  // namespace facet::cpu

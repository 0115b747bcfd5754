// Per-corner tangents of a triangle mesh by MikkTSpace (M. S. Mikkelsen,
// "Simulation of Wrinkled Surfaces Revisited", MSc thesis, University of
// Copenhagen, 2008), the tangent frame glTF 2.0 prescribes for meshes without
// TANGENT: a normal map baked against it reads back unchanged. It follows
// mikktspace.c's genTangSpaceDefault, i.e. an angular threshold of 180
// degrees, so a vertex splits only where its texture mapping mirrors or
// tears, never because the s-directions around it turn.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace facet::scene {

// One corner of a triangle as the algorithm reads it; `normal` unit length.
struct TangentCorner {
  glm::dvec3 position;
  glm::dvec3 normal;
  glm::dvec2 texcoord;  // MikkTSpace's convention: v grows up the image
};

// For each corner of `corners` (three per triangle, in order): xyz the unit
// tangent (along dP/du, orthogonal to the corner's normal), w = +1 or -1 such
// that w * cross(normal, tangent) is the bitangent along dP/dv.
// Corners the mapping gives no direction (every triangle around them without
// texture area) get the coordinate axis least aligned with the normal, made
// orthogonal to it, and w = +1.
// Throws std::invalid_argument when corners.size() is not a multiple of 3;
// nothing for degenerate triangles or mappings.
std::vector<glm::dvec4> mikktspaceTangents(const std::vector<TangentCorner>& corners);

}  // namespace facet::scene

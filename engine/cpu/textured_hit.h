// What the CPU reference fetches of a textured material at a hit
// (rules/shading/surface_at_hit.h takes it from there): every slot read at
// the hit's coordinates of the set it names, with the ray cone's footprint,
// the base colour times the vertex colour.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

#include "engine/cpu/ray.h"
#include "materials/material.h"
#include "rules/rules.h"
#include "scenes/subdivision_surface.h"
#include "scenes/texture.h"

namespace facet::cpu {

// Material textures `t` at `hit` on `surface`, seen along `direction`, of
// geometric normal ng, the ray's cone widening by `coneSpread` per unit of
// distance.
rules::f64::MaterialTexels materialTexels(const scene::SubdivisionSurface& surface, const SurfaceHit& hit,
                                          const std::vector<scene::Texture>& textures,
                                          const materials::MaterialTextures& t, const glm::dvec3& ng,
                                          const glm::dvec3& direction, double coneSpread);

// The glTF factors of textures `t`, as the rule takes them.
rules::f64::TexturedFactors texturedFactors(const materials::MaterialTextures& t);

}  // namespace facet::cpu

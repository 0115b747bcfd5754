// A textured material at a hit of the CPU reference
// (rules/shading/textured_material.h): every slot read at the hit's
// coordinates of the set it names, the base colour times the vertex colour,
// and the layers' textures. The GPU's counterpart is surface.comp's
// textured_hit.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

#include "engine/cpu/ray.h"
#include "materials/material.h"
#include "rules/rules.h"
#include "scenes/subdivision_surface.h"
#include "scenes/texture.h"

namespace facet::cpu {

// Material textures `t` at `hit` on `surface`, seen along `direction` with
// the normals n and ng facing the eye, the ray's cone widening by
// `coneSpread` per unit of distance, and emission factor `emission`.
rules::f64::TexturedSurface texturedHit(const scene::SubdivisionSurface& surface, const SurfaceHit& hit,
                                        const std::vector<scene::Texture>& textures,
                                        const materials::MaterialTextures& t, const rules::f64::BrdfParams& params,
                                        const glm::dvec3& n, const glm::dvec3& ng, const glm::dvec3& direction,
                                        const glm::dvec3& emission, double coneSpread);

}  // namespace facet::cpu

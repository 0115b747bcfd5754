// Energy compensation as the surface kernel applies it (docs/shading.md,
// "Energy compensation"): the factor on a material's specular lobe, read
// from the scene's compensation tables (engine/ibl/compensation_tables.h)
// like the CPU reference's ibl::specularScale. Needs `frame` and the
// specialization constant COMPENSATION (1 when some material is compensated).
#ifndef FACET_RAYCAST_ENERGY_COMPENSATION_GLSL
#define FACET_RAYCAST_ENERGY_COMPENSATION_GLSL

#include "rules/language.glsl"
#include "rules/shading/brdf.h"
#include "rules/shading/dfg.h"

#include "compute/raycast/shading/dfg_tables.glsl"

layout(set = 0, binding = 17) uniform samplerBuffer compensationTables;

// vec3(1) for a material without compensation, or in a scene with none.
vec3 material_specular_scale(uint table, BrdfParams p, float nv, bool transmissive, bool outside) {
  if (COMPENSATION == 0 || table == FACET_NO_COMPENSATION) return vec3(1.0);
  int size = int(frame.compensationSize);
  uint read = uint(compensation_table(int(table), transmissive, outside));
  return material_compensation(p, transmissive,
                               dfg_table_lookup(compensationTables, read * uint(size * size), size, nv,
                                                isotropic_equivalent_alpha(p)));
}

#endif

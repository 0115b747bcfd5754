// DFG tables in a texel buffer, as engine/ibl/prefiltered_environment.h lays
// one out: size x size (scale, bias) texels from `first`, read bilinearly at
// dfg_grid_position (rules/shading/dfg.h) like ibl::dfgLookup.
#ifndef FACET_RAYCAST_DFG_TABLES_GLSL
#define FACET_RAYCAST_DFG_TABLES_GLSL

#include "rules/language.glsl"
#include "rules/shading/dfg.h"

vec2 dfg_table_lookup(samplerBuffer tables, uint first, int size, float nv, float alpha) {
  vec2 position = dfg_grid_position(nv, alpha, size);
  int i0 = int(floor(position.x)), j0 = int(floor(position.y));
  int i1 = min(i0 + 1, size - 1), j1 = min(j0 + 1, size - 1);
  float fx = position.x - float(i0), fy = position.y - float(j0);
  int row0 = int(first) + j0 * size, row1 = int(first) + j1 * size;
  return mix(mix(texelFetch(tables, row0 + i0).xy, texelFetch(tables, row0 + i1).xy, fx),
             mix(texelFetch(tables, row1 + i0).xy, texelFetch(tables, row1 + i1).xy, fx), fy);
}

#endif

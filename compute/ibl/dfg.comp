// One DFG table: entry (i, j) at n.v = (i + 1) / size and sqrt(alpha) =
// j / (size - 1) (engine/ibl/prefiltered_environment.h). The BRDF models are
// specialization constants, so each (D, G) pair keeps only its branches.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/grid/config.h"
#include "rules/shading/dfg.h"

layout(local_size_x = FACET_IBL_TILE_SIZE, local_size_y = FACET_IBL_TILE_SIZE) in;

layout(constant_id = 0) const int D_MODEL = 0;
layout(constant_id = 1) const int G_MODEL = 4;

layout(set = 0, binding = 0, std140) uniform Params {
  int size;
  int samples;
};
layout(set = 0, binding = 1, std430) writeonly buffer Table { vec2 scaleBias[]; };

void main() {
  int i = int(gl_GlobalInvocationID.x);
  int j = int(gl_GlobalInvocationID.y);
  if (i >= size || j >= size) return;
  scaleBias[j * size + i] = dfg_integrals(D_MODEL, G_MODEL, dfg_grid_nv(i, size), dfg_grid_alpha(j, size), samples);
}

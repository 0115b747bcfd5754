// The grid of the kernels that run one invocation per item: workgroups
// FACET_WORKGROUP_SIZE wide, spilling into y past
// FACET_MAX_WORKGROUPS_PER_DIMENSION (rules/grid/workgroup_grid.h
// sizes it, on the host and in dispatch_args.comp).
#ifndef FACET_RAYCAST_WORKGROUP_GLSL
#define FACET_RAYCAST_WORKGROUP_GLSL

#include "rules/language.glsl"
#include "rules/grid/config.h"

layout(local_size_x = FACET_WORKGROUP_SIZE) in;

uint invocation_index() {
  return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * uint(FACET_WORKGROUP_SIZE);
}

#endif

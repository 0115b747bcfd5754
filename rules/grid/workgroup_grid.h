// The grid of workgroups that covers `invocations` one per item,
// FACET_WORKGROUP_SIZE wide and spilling into y past
// FACET_MAX_WORKGROUPS_PER_DIMENSION, as invocation_index()
// (compute/raycast/common/workgroup.glsl) reads it.

#ifndef FACET_RULE_GRID_WORKGROUP_GRID
#define FACET_RULE_GRID_WORKGROUP_GRID

#include "rules/grid/config.h"

FACET_FN uvec3 workgroup_grid(uint invocations) {
  uint size = uint(FACET_WORKGROUP_SIZE);
  uint groups = (invocations + size - 1u) / size;
  uint x = min(groups, uint(FACET_MAX_WORKGROUPS_PER_DIMENSION));
  return uvec3(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u);
}

#endif

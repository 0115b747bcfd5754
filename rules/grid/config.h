// Plain macros: the compute grid of the kernels that run one invocation per
// item (compute/raycast/common/workgroup.glsl) and the host code that
// dispatches them.

#ifndef FACET_RULE_GRID_CONFIG
#define FACET_RULE_GRID_CONFIG

// Invocations per workgroup, along x.
#define FACET_WORKGROUP_SIZE 64
// Vulkan's guaranteed maxComputeWorkGroupCount per dimension: larger grids
// spill into y.
#define FACET_MAX_WORKGROUPS_PER_DIMENSION 65535
// The image-based-lighting kernels work on 2D tiles of this side.
#define FACET_IBL_TILE_SIZE 8

#endif

// The cell a BVH reference names. The including kernel declares the texel
// buffers bvhNodes and patchHeaders. Needs micro_grid.glsl.
#ifndef FACET_RAYCAST_CELL_REFERENCE_GLSL
#define FACET_RAYCAST_CELL_REFERENCE_GLSL

// The cell a reference names: its node of 2 x 2 cells says which patch and
// where (compute/layout/wide_bvh.h).
Cell cell_of(uint reference) {
  uint node = (reference & ~FACET_BVH4_CELL) >> 2u, slot = reference & 3u;
  uvec4 info = texelFetch(bvhNodes, int(node * FACET_BVH4_TEXELS + FACET_BVH4_INFO));
  return patch_cell(info.x, 2u * info.y + (slot & 1u), 2u * info.z + (slot >> 1u));
}

#endif

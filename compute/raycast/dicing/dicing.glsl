// What the dicing kernels share: which object an index of the concatenated
// arrays belongs to, and where a patch's quadtree nodes are
// (compute/layout/wide_bvh.h, compute/layout/raycast_layout.h).
#ifndef FACET_RAYCAST_DICING_GLSL
#define FACET_RAYCAST_DICING_GLSL

// Which of ObjectRange's starts object_of() compares.
const int RANGE_PATCHES = 0;
const int RANGE_BLOCKS = 1;
const int RANGE_GRID_VERTICES = 2;
const int RANGE_EDGE_MIDPOINTS = 3;

uint range_start(ObjectRange range, int kind) {
  return kind == RANGE_PATCHES ? range.firstPatch : kind == RANGE_BLOCKS ? range.firstBlock
                                                  : kind == RANGE_GRID_VERTICES ? range.firstGridVertex
                                                                                : range.firstEdgeMidpoint;
}

// The last object whose range of `kind` starts at or before `index` (objects
// are in order, so an empty one gives way to its successor).
uint object_of(uint index, int kind) {
  uint object = 0u;
  for (uint o = 1u; o < frame.objectCount; ++o)
    if (range_start(objects[o], kind) <= index) object = o;
  return object;
}

// Nodes of a quadtree level l: (4^l - 1) / 3 come before it.
uint level_start(uint level) { return ((1u << (2u * level)) - 1u) / 3u; }

uint quadtree_node(ObjectRange range, uint localPatch, uint level, uint x, uint y) {
  return range.firstQuadtreeNode + localPatch * range.quadtreeNodes + level_start(level) + (y << level) + x;
}

#endif

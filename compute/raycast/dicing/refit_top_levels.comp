// One invocation: the top levels' boxes, built on the CPU from the patches'
// control hulls, shrunk to what the dicing kernels bounded below them (the
// hull of a whole patch is looser than its cells' bounds together): node by
// node, children first, each slot the union of its child's boxes.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/wide_bvh.h"

layout(local_size_x = 1) in;

layout(set = 0, binding = 1, rgba32ui) uniform uimageBuffer bvhNodes;
layout(set = 0, binding = 26, std430) readonly buffer RefitOrder { uint refitOrder[]; };

#include "compute/raycast/dicing/node_boxes.glsl"

void main() {
  for (uint n = 0u; n < uint(refitOrder.length()); ++n) {
    uint node = refitOrder[n];
    NodeBoxes boxes = load_boxes(node);
    uvec4 children = load_references(node);
    for (int slot = 0; slot < 4; ++slot)
      if (children[slot] != FACET_BVH4_EMPTY) set_to_union(boxes, slot, children[slot]);
    store_boxes(node, boxes);
  }
}

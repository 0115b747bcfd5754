// The upper levels of every patch's quadtree, bottom up, one invocation per
// patch: each slot holds the union of a child node's boxes, or is empty
// where the child covers no cell (k below the quadtree's side).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/layout/wide_bvh.h"
#include "compute/raycast/dicing/dicing.glsl"

layout(set = 0, binding = 1, rgba32ui) uniform uimageBuffer bvhNodes;

#include "compute/raycast/dicing/node_boxes.glsl"

void main() {
  uint patchIndex = invocation_index();
  if (patchIndex >= frame.patchCount) return;
  ObjectRange range = objects[object_of(patchIndex, RANGE_PATCHES)];
  uint localPatch = patchIndex - range.firstPatch;
  for (int level = int(range.quadtreeLevels) - 2; level >= 0; --level) {
    uint side = 1u << uint(level);
    for (uint node = 0u; node < side * side; ++node) {
      uint x = node % side, y = node / side;
      NodeBoxes boxes = NodeBoxes(vec4[3](vec4(0.0), vec4(0.0), vec4(0.0)), vec4[3](vec4(0.0), vec4(0.0), vec4(0.0)));
      uvec4 references = uvec4(FACET_BVH4_EMPTY);
      for (uint slot = 0u; slot < 4u; ++slot) {
        uint child = quadtree_node(range, localPatch, uint(level) + 1u, 2u * x + (slot & 1u), 2u * y + (slot >> 1u));
        if (set_to_union(boxes, int(slot), child)) references[slot] = child;
      }
      uint parent = quadtree_node(range, localPatch, uint(level), x, y);
      store_boxes(parent, boxes);
      imageStore(bvhNodes, int(parent * FACET_BVH4_TEXELS + FACET_BVH4_REFERENCES), references);
    }
  }
}

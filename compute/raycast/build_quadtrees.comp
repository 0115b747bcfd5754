// The upper levels of every patch's quadtree, bottom up, one invocation per
// patch: each slot holds the union of a child node's boxes, or is empty
// where the child covers no cell (k below the quadtree's side).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/scene_bindings.glsl"
#include "compute/shared/wide_bvh.h"
#include "compute/raycast/dicing.glsl"

layout(set = 0, binding = 1, rgba32ui) uniform uimageBuffer bvhNodes;

void main() {
  uint patchIndex = invocation_index();
  if (patchIndex >= frame.patchCount) return;
  ObjectRange range = objects[object_of(patchIndex, RANGE_PATCHES)];
  uint localPatch = patchIndex - range.firstPatch;
  for (int level = int(range.quadtreeLevels) - 2; level >= 0; --level) {
    uint side = 1u << uint(level);
    for (uint node = 0u; node < side * side; ++node) {
      uint x = node % side, y = node / side;
      vec4 lo[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0)), hi[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
      uvec4 references = uvec4(FACET_BVH4_EMPTY);
      for (uint slot = 0u; slot < 4u; ++slot) {
        uint child = quadtree_node(range, localPatch, uint(level) + 1u, 2u * x + (slot & 1u), 2u * y + (slot >> 1u));
        int base = int(child * FACET_BVH4_TEXELS);
        uvec4 grandchildren = imageLoad(bvhNodes, base + int(FACET_BVH4_REFERENCES)).xyzw;
        bvec4 used = notEqual(grandchildren, uvec4(FACET_BVH4_EMPTY));
        if (!any(used)) continue;
        for (int axis = 0; axis < 3; ++axis) {
          vec4 l = mix(vec4(uintBitsToFloat(0x7f800000u)), uintBitsToFloat(imageLoad(bvhNodes, base + 2 * axis)), used);
          vec4 h = mix(vec4(-uintBitsToFloat(0x7f800000u)), uintBitsToFloat(imageLoad(bvhNodes, base + 2 * axis + 1)), used);
          lo[axis][slot] = min(min(l.x, l.y), min(l.z, l.w));
          hi[axis][slot] = max(max(h.x, h.y), max(h.z, h.w));
        }
        references[slot] = child;
      }
      int base = int(quadtree_node(range, localPatch, uint(level), x, y) * FACET_BVH4_TEXELS);
      for (int axis = 0; axis < 3; ++axis) {
        imageStore(bvhNodes, base + 2 * axis, floatBitsToUint(lo[axis]));
        imageStore(bvhNodes, base + 2 * axis + 1, floatBitsToUint(hi[axis]));
      }
      imageStore(bvhNodes, base + int(FACET_BVH4_REFERENCES), references);
    }
  }
}

// Reading and writing a 4-wide node's child boxes in place, for the kernels
// that build the BVH bottom up. The including kernel declares bvhNodes as
// an rgba32ui storage texel buffer.
#ifndef FACET_RAYCAST_NODE_BOXES_GLSL
#define FACET_RAYCAST_NODE_BOXES_GLSL

// The four child boxes as structure of arrays, one vec4 per bound.
struct NodeBoxes {
  vec4 lo[3];
  vec4 hi[3];
};

NodeBoxes load_boxes(uint node) {
  int base = int(node * FACET_BVH4_TEXELS);
  NodeBoxes b;
  for (int axis = 0; axis < 3; ++axis) {
    b.lo[axis] = uintBitsToFloat(imageLoad(bvhNodes, base + 2 * axis));
    b.hi[axis] = uintBitsToFloat(imageLoad(bvhNodes, base + 2 * axis + 1));
  }
  return b;
}

void store_boxes(uint node, NodeBoxes b) {
  int base = int(node * FACET_BVH4_TEXELS);
  for (int axis = 0; axis < 3; ++axis) {
    imageStore(bvhNodes, base + 2 * axis, floatBitsToUint(b.lo[axis]));
    imageStore(bvhNodes, base + 2 * axis + 1, floatBitsToUint(b.hi[axis]));
  }
}

uvec4 load_references(uint node) { return imageLoad(bvhNodes, int(node * FACET_BVH4_TEXELS + FACET_BVH4_REFERENCES)); }

// Slot `slot` of `boxes` set to the box around `node`'s used children;
// false (and nothing set) when it has none.
bool set_to_union(inout NodeBoxes boxes, int slot, uint node) {
  bvec4 used = notEqual(load_references(node), uvec4(FACET_BVH4_EMPTY));
  if (!any(used)) return false;
  NodeBoxes child = load_boxes(node);
  const vec4 infinite = vec4(uintBitsToFloat(0x7f800000u));
  for (int axis = 0; axis < 3; ++axis) {
    vec4 l = mix(infinite, child.lo[axis], used), h = mix(-infinite, child.hi[axis], used);
    boxes.lo[axis][slot] = min(min(l.x, l.y), min(l.z, l.w));
    boxes.hi[axis][slot] = max(max(h.x, h.y), max(h.z, h.w));
  }
  return true;
}

#endif

// One node of a 4-wide BVH (compute/layout/wide_bvh.h's layout) against a
// ray: where it enters each child box, and the children in that order. The
// including kernel declares the texel buffer `bvhNodes`. Needs ray.glsl.
#ifndef FACET_RAYCAST_WIDE_BVH_NODE_GLSL
#define FACET_RAYCAST_WIDE_BVH_NODE_GLSL

// Where the ray enters each of the node's four child boxes within
// [tMin, tMax], +inf for those it misses and for empty slots.
vec4 child_entries(uint node, vec3 origin, vec3 inverseDirection, float tMin, float tMax, out uvec4 children) {
  int base = int(node * FACET_BVH4_TEXELS);
  vec4 x0 = (uintBitsToFloat(texelFetch(bvhNodes, base)) - origin.x) * inverseDirection.x;
  vec4 x1 = (uintBitsToFloat(texelFetch(bvhNodes, base + 1)) - origin.x) * inverseDirection.x;
  vec4 y0 = (uintBitsToFloat(texelFetch(bvhNodes, base + 2)) - origin.y) * inverseDirection.y;
  vec4 y1 = (uintBitsToFloat(texelFetch(bvhNodes, base + 3)) - origin.y) * inverseDirection.y;
  vec4 z0 = (uintBitsToFloat(texelFetch(bvhNodes, base + 4)) - origin.z) * inverseDirection.z;
  vec4 z1 = (uintBitsToFloat(texelFetch(bvhNodes, base + 5)) - origin.z) * inverseDirection.z;
  children = texelFetch(bvhNodes, base + int(FACET_BVH4_REFERENCES));
  vec4 enter = max(max(min(x0, x1), min(y0, y1)), max(min(z0, z1), vec4(tMin)));
  vec4 leave = min(min(max(x0, x1), max(y0, y1)), min(max(z0, z1), vec4(tMax))) * SLAB_WIDENING;
  bvec4 hit = bvec4(uvec4(lessThanEqual(enter, leave)) & uvec4(notEqual(children, uvec4(FACET_BVH4_EMPTY))));
  return mix(vec4(INFINITE_DISTANCE), enter, hit);
}

void order_children(inout vec4 entry, inout uvec4 children, int a, int b) {
  bool swap = entry[b] < entry[a];
  float e = entry[a];
  uint c = children[a];
  entry[a] = swap ? entry[b] : e;
  entry[b] = swap ? e : entry[b];
  children[a] = swap ? children[b] : c;
  children[b] = swap ? c : children[b];
}

// The four children by entry distance, nearest first (a five-exchange
// sorting network).
void sort_children(inout vec4 entry, inout uvec4 children) {
  order_children(entry, children, 0, 1);
  order_children(entry, children, 2, 3);
  order_children(entry, children, 0, 2);
  order_children(entry, children, 1, 3);
  order_children(entry, children, 1, 2);
}

#endif

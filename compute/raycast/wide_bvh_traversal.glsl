// Depth-first traversal of the scene's 4-wide BVH (compute/shared/wide_bvh.h)
// read through the texel buffer `bvhNodes`: nearest child first, the others
// on a private stack with their entry distance, so that entries beyond the
// closest hit are dropped when popped. Reaching a cell calls
// finish_cell(ray, reference, best), which the including file defines.
// Needs ray.glsl.
#ifndef FACET_RAYCAST_WIDE_BVH_TRAVERSAL_GLSL
#define FACET_RAYCAST_WIDE_BVH_TRAVERSAL_GLSL

const int TRAVERSAL_STACK = 3 * int(FACET_BVH4_MAX_DEPTH);

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

void traverse(Ray ray, bool anyHit, inout Hit best) {
  vec3 inverseDirection = safe_inverse(ray.direction);
  uint stackReference[TRAVERSAL_STACK];
  float stackEntry[TRAVERSAL_STACK];
  int top = 0;
  uint reference = frame.rootNode;
  while (true) {
    if ((reference & FACET_BVH4_CELL) != 0u) {
      finish_cell(ray, reference, best);
      if (anyHit && best.patchIndex != FACET_NO_HIT) return;
    } else {
      uvec4 children;
      vec4 entry = child_entries(reference, ray.origin, inverseDirection, ray.tMin, best.t, children);
      // Nearest first: a sorting network orders the four (closest hit
      // only; any hit takes them as they come), the far ones are stacked.
      if (!anyHit) {
        order_children(entry, children, 0, 1);
        order_children(entry, children, 2, 3);
        order_children(entry, children, 0, 2);
        order_children(entry, children, 1, 3);
        order_children(entry, children, 1, 2);
      }
      for (int c = 3; c > 0; --c) {
        if (entry[c] == INFINITE_DISTANCE) continue;
        stackReference[top] = children[c];
        stackEntry[top] = entry[c];
        ++top;
      }
      if (entry[0] != INFINITE_DISTANCE) {
        reference = children[0];
        continue;
      }
    }
    while (top > 0 && !(stackEntry[top - 1] < best.t)) --top;
    if (top == 0) return;
    reference = stackReference[--top];
  }
}

#endif

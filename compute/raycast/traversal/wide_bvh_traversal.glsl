// Depth-first traversal of the scene's 4-wide BVH (compute/layout/wide_bvh.h)
// read through the texel buffer `bvhNodes`: nearest child first, the others
// on a private stack with their entry distance, so that entries beyond the
// closest hit are dropped when popped. Reaching a cell calls
// finish_cell(ray, reference, best), which the including file defines.
// Needs ray.glsl.
#ifndef FACET_RAYCAST_WIDE_BVH_TRAVERSAL_GLSL
#define FACET_RAYCAST_WIDE_BVH_TRAVERSAL_GLSL

#include "compute/raycast/traversal/wide_bvh_node.glsl"

const int TRAVERSAL_STACK = 3 * int(FACET_BVH4_MAX_DEPTH);

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
      if (!anyHit) sort_children(entry, children);
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

// facet's closest hit of each continuation ray of a list (intersect.comp
// with PATHS = 1, tessellated) with what its traversal did: per ray, the BVH
// nodes whose four children were tested and the micro-grid cells finished,
// written as a uvec4 (nodes, cells, cells, 0), the ceiling's
// layout of (nodes, leaves, triangles), where intersect.comp writes its hit. The traversal is
// compute/raycast/traversal/wide_bvh_traversal.glsl with two counters, put in
// its place (its include guard defined first); the finish and the node test
// are facet's own. Only the benchmark runs it; the production kernel counts
// nothing.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/common/trace_bindings.glsl"

layout(constant_id = 0) const int METHOD = 1;

layout(set = 0, binding = 9, std430) writeonly buffer Counts { uvec4 counts[]; };
layout(set = 0, binding = 33, std430) readonly buffer PathRays { PathRayRecord pathRays[]; };

void defer_cell(uint reference) {}  // the exact method's fallbacks: not counted here

#include "compute/raycast/common/ray.glsl"
#include "compute/raycast/traversal/wide_bvh_node.glsl"

void finish_cell(Ray ray, uint reference, inout Hit best);

uint nodesTested = 0u, cellsFinished = 0u;

#define FACET_RAYCAST_WIDE_BVH_TRAVERSAL_GLSL
const int COUNTED_STACK = 3 * int(FACET_BVH4_MAX_DEPTH);

void traverse(Ray ray, bool anyHit, inout Hit best) {
  vec3 inverseDirection = safe_inverse(ray.direction);
  uint stackReference[COUNTED_STACK];
  float stackEntry[COUNTED_STACK];
  int top = 0;
  uint reference = frame.rootNode;
  while (true) {
    if ((reference & FACET_BVH4_CELL) != 0u) {
      ++cellsFinished;
      finish_cell(ray, reference, best);
    } else {
      ++nodesTested;
      uvec4 children;
      vec4 entry = child_entries(reference, ray.origin, inverseDirection, ray.tMin, best.t, children);
      sort_children(entry, children);
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

#include "compute/raycast/traversal/trace.glsl"

void main() {
  uint index = invocation_index();
  if (index >= counters.pathRays) return;
  Hit hit = trace(to_ray(pathRays[index].ray), false);
  counts[index] = uvec4(nodesTested, cellsFinished, cellsFinished, 0u);
}

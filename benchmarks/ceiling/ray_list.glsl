// The ceiling's closest hit of each ray of a given list (incoherent rays,
// benchmarks/incoherent/): frame.screen.x rays, (t, triangle) per ray, (inf,
// EMPTY) on a miss. With CEILING_COUNT defined, also the BVH nodes visited,
// leaves reached and triangles tested per ray (a separate pipeline; the timed one counts
// nothing).
#ifndef CEILING_RAY_LIST_GLSL
#define CEILING_RAY_LIST_GLSL

#include "benchmarks/ceiling/ceiling.glsl"

layout(set = 0, binding = 3, std430) readonly buffer Rays { RayRecord rays[]; };
layout(set = 0, binding = 4, std430) writeonly buffer Hits { uvec2 hits[]; };
#ifdef CEILING_COUNT
layout(set = 0, binding = 5, std430) writeonly buffer Counts { uvec4 counts[]; };
#endif

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= uint(frame.screen.x)) return;
  RayRecord r = rays[index];
  // The ceiling's traversal starts at t = 0: the ray's own start (facet's
  // continuation rays leave at tMin = the offset) is moved along it instead.
  vec3 o = vec3(r.originX, r.originY, r.originZ), d = vec3(r.directionX, r.directionY, r.directionZ);
  o += d * r.tMin;
  float t = r.tMax;
  uint tri = trace(o, d, t, false);
  hits[index] = uvec2(floatBitsToUint(tri == EMPTY ? INF : t + r.tMin), tri);
#ifdef CEILING_COUNT
  counts[index] = uvec4(ceilingNodes, ceilingLeaves, ceilingTriangles, 0u);
#endif
}

#endif

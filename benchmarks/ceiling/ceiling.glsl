// The ceiling kernels' shared part: a BVH4 of plain triangles, traversed
// depth-first, nearest child first. Everything is relative to the camera eye,
// so camera rays start at the origin and float keeps its precision where the
// picture is. Layouts are written by ceiling_bench.cpp.
//
//   bvhNodes  facet's node layout (compute/layout/wide_bvh.h), read by the
//             same node test (compute/raycast/traversal/wide_bvh_node.glsl)
//   tris      3 RGBA32F texels per triangle: v0, v1 - v0, v2 - v0
//
// A reference is a node index, FACET_BVH4_EMPTY, or LEAF | (count - 1) << 27
// | first triangle. Texel fetches, not SSBO loads: lavapipe turns an SSBO
// load at a per-lane index into a loop over lanes, a texel fetch is one
// gather.
#ifndef CEILING_GLSL
#define CEILING_GLSL

#include "compute/layout/raycast_layout.h"
#include "compute/layout/wide_bvh.h"
#include "compute/raycast/common/ray.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std140) uniform Frame {
  vec4 forward;
  vec4 right;
  vec4 up;
  vec4 light;   // xyz: the point light; w: how far shadow rays start off the surface
  vec4 screen;  // width, height, tan(fov / 2) * aspect, tan(fov / 2)
} frame;
layout(set = 0, binding = 1) uniform usamplerBuffer bvhNodes;
layout(set = 0, binding = 2) uniform samplerBuffer tris;

#include "compute/raycast/traversal/wide_bvh_node.glsl"

const uint LEAF = 0x80000000u;
const uint EMPTY = FACET_BVH4_EMPTY;
const int STACK = 64;  // 3 per level; the builder checks the depth
const float INF = INFINITE_DISTANCE;

// With CEILING_COUNT (ray_list.glsl's counted variant): what trace() did.
#ifdef CEILING_COUNT
uint ceilingNodes = 0u, ceilingLeaves = 0u, ceilingTriangles = 0u;
#define CEILING_COUNTED(counter) ++counter
#else
#define CEILING_COUNTED(counter)
#endif

uint pixel_count() { return uint(frame.screen.x) * uint(frame.screen.y); }

// rules/camera/camera.h's pinhole, pixel centres.
vec3 camera_direction(uint pixel) {
  uint width = uint(frame.screen.x);
  float x = float(pixel % width) + 0.5, y = float(pixel / width) + 0.5;
  float sx = (2.0 * x / frame.screen.x - 1.0) * frame.screen.z;
  float sy = (1.0 - 2.0 * y / frame.screen.y) * frame.screen.w;
  return normalize(frame.forward.xyz + sx * frame.right.xyz + sy * frame.up.xyz);
}

// Möller-Trumbore: t in (0, tMax), else tMax.
float intersect_triangle(uint tri, vec3 o, vec3 d, float tMax) {
  int base = int(tri) * 3;
  vec3 v0 = texelFetch(tris, base).xyz, e1 = texelFetch(tris, base + 1).xyz, e2 = texelFetch(tris, base + 2).xyz;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  float invDet = 1.0 / det;
  vec3 s = o - v0;
  float u = dot(s, p) * invDet;
  vec3 q = cross(s, e1);
  float v = dot(d, q) * invDet;
  float t = dot(e2, q) * invDet;
  return (det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t < tMax) ? t : tMax;
}

// The nearest triangle hit by o + t d, 0 < t < tMax (or with anyHit, the
// first found): its index, or EMPTY; tMax becomes its t. Callers pass
// anyHit as a constant, so each kernel gets its own specialised loop.
uint trace(vec3 o, vec3 d, inout float tMax, bool anyHit) {
  vec3 inv = safe_inverse(d);
  uint stackRef[STACK];
  float stackT[STACK];
  int top = 0;
  uint ref = 0u;  // the root is always an inner node
  uint hit = EMPTY;
  while (true) {
    bool next = false;
    if ((ref & LEAF) != 0u) {
      CEILING_COUNTED(ceilingLeaves);
      uint first = ref & 0x07ffffffu, last = first + ((ref >> 27) & 15u);
      for (uint i = first; i <= last; ++i) {
        CEILING_COUNTED(ceilingTriangles);
        float t = intersect_triangle(i, o, d, tMax);
        if (t < tMax) {
          tMax = t;
          hit = i;
          if (anyHit) return hit;
        }
      }
    } else {
      uvec4 r;
      CEILING_COUNTED(ceilingNodes);
      vec4 t = child_entries(ref, o, inv, 0.0, tMax, r);
      if (!anyHit) sort_children(t, r);
      for (int c = 3; c > 0; --c) {
        if (t[c] < INF) {
          stackRef[top] = r[c];
          stackT[top] = t[c];
          ++top;
        }
      }
      if (t[0] < INF) {
        ref = r[0];
        next = true;
      }
    }
    // Entries beyond the best hit so far are dropped as they are popped.
    while (!next && top > 0) {
      --top;
      if (stackT[top] < tMax) {
        ref = stackRef[top];
        next = true;
      }
    }
    if (!next) return hit;
  }
}

#endif

// The ceiling kernels' shared part: a BVH4 of plain triangles, traversed
// depth-first, nearest child first. Everything is relative to the camera eye,
// so camera rays start at the origin and float keeps its precision where the
// picture is. Layouts are written by ceiling_bench.cpp.
//
//   nodes  7 RGBA32UI texels per node: lo.x, hi.x, lo.y, hi.y, lo.z, hi.z of
//          its 4 children (float bits), then their 4 references
//   tris   3 RGBA32F texels per triangle: v0, v1 - v0, v2 - v0
//
// A reference is a node index, EMPTY, or LEAF | (count - 1) << 27 | first
// triangle. Texel fetches, not SSBO loads: lavapipe turns an SSBO load at a
// per-lane index into a loop over lanes, a texel fetch is one gather.
#ifndef CEILING_GLSL
#define CEILING_GLSL

layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std140) uniform Frame {
  vec4 forward;
  vec4 right;
  vec4 up;
  vec4 light;   // xyz: the point light; w: how far shadow rays start off the surface
  vec4 screen;  // width, height, tan(fov / 2) * aspect, tan(fov / 2)
} frame;
layout(set = 0, binding = 1) uniform usamplerBuffer nodes;
layout(set = 0, binding = 2) uniform samplerBuffer tris;

const uint LEAF = 0x80000000u;
const uint EMPTY = 0xffffffffu;
const int STACK = 64;  // 3 per level; the builder checks the depth
const float INF = 1.0 / 0.0;
// (lo - o) * inv rounds; widening the exit keeps grazing rays inside the box.
const float WIDEN = 1.0 + 4.0 * 1.1920929e-7;

uint pixel_count() { return uint(frame.screen.x) * uint(frame.screen.y); }

// compute/shared/camera.h's pinhole, pixel centres.
vec3 camera_direction(uint pixel) {
  uint width = uint(frame.screen.x);
  float x = float(pixel % width) + 0.5, y = float(pixel / width) + 0.5;
  float sx = (2.0 * x / frame.screen.x - 1.0) * frame.screen.z;
  float sy = (1.0 - 2.0 * y / frame.screen.y) * frame.screen.w;
  return normalize(frame.forward.xyz + sx * frame.right.xyz + sy * frame.up.xyz);
}

// 1/0 is fine, but 0 * inf (a box face through the origin) is NaN.
vec3 safe_inverse(vec3 d) {
  vec3 magnitude = max(abs(d), vec3(1e-30));
  return mix(vec3(-1.0), vec3(1.0), greaterThanEqual(d, vec3(0.0))) / magnitude;
}

// Entry distance of each child box within [0, tMax], INF where missed or empty.
vec4 child_entries(uint node, vec3 o, vec3 inv, float tMax, out uvec4 refs) {
  int base = int(node) * 7;
  vec4 x0 = (uintBitsToFloat(texelFetch(nodes, base)) - o.x) * inv.x;
  vec4 x1 = (uintBitsToFloat(texelFetch(nodes, base + 1)) - o.x) * inv.x;
  vec4 y0 = (uintBitsToFloat(texelFetch(nodes, base + 2)) - o.y) * inv.y;
  vec4 y1 = (uintBitsToFloat(texelFetch(nodes, base + 3)) - o.y) * inv.y;
  vec4 z0 = (uintBitsToFloat(texelFetch(nodes, base + 4)) - o.z) * inv.z;
  vec4 z1 = (uintBitsToFloat(texelFetch(nodes, base + 5)) - o.z) * inv.z;
  refs = texelFetch(nodes, base + 6);
  vec4 enter = max(max(min(x0, x1), min(y0, y1)), max(min(z0, z1), vec4(0.0)));
  vec4 leave = min(min(max(x0, x1), max(y0, y1)), min(max(z0, z1), vec4(tMax))) * WIDEN;
  bvec4 hit = bvec4(uvec4(lessThanEqual(enter, leave)) & uvec4(notEqual(refs, uvec4(EMPTY))));
  return mix(vec4(INF), enter, hit);
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

#define SORT2(a, b)                  \
  if (t[b] < t[a]) {                 \
    float ft = t[a]; t[a] = t[b]; t[b] = ft; \
    uint fr = r[a]; r[a] = r[b]; r[b] = fr;  \
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
      uint first = ref & 0x07ffffffu, last = first + ((ref >> 27) & 15u);
      for (uint i = first; i <= last; ++i) {
        float t = intersect_triangle(i, o, d, tMax);
        if (t < tMax) {
          tMax = t;
          hit = i;
          if (anyHit) return hit;
        }
      }
    } else {
      uvec4 r;
      vec4 t = child_entries(ref, o, inv, tMax, r);
      if (!anyHit) {
        SORT2(0, 1) SORT2(2, 3) SORT2(0, 2) SORT2(1, 3) SORT2(1, 2)
      }
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

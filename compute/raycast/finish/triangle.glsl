// The ray against one micro-triangle. Needs ray.glsl and trace_bindings.glsl.
#ifndef FACET_RAYCAST_TRIANGLE_GLSL
#define FACET_RAYCAST_TRIANGLE_GLSL

#include "rules/language.glsl"
#include "rules/surface/ray_triangle.h"

// The shared rule (rules/surface/ray_triangle.h), `shear` the ray's frame; on a hit in [tMin, best.t)
// that the object does not pass over (its normal is e1 x e2, as the CPU's;
// hit_filter.glsl), records it with the grid step of the hit point (the
// steps of the corners interpolated).
void intersect_triangle(Ray ray, RayShear shear, vec3 a, vec3 b, vec3 c, vec2 stepA, vec2 stepB, vec2 stepC,
                        float rate, uint patchIndex, uint object, inout Hit best) {
  TriangleHit crossing;
  if (!ray_hits_triangle(shear, ray.origin, a, b, c, crossing)) return;
  float t = crossing.t, wb = crossing.wb, wc = crossing.wc;
  if (t < ray.tMin || t >= best.t) return;
  vec3 e1 = b - a, e2 = c - a;
  vec2 st = ((1.0 - wb - wc) * stepA + wb * stepB + wc * stepC) / rate;
  if (passes_over(object, ray.direction, cross(e1, e2), patchIndex, st, t)) return;
  best.t = t;
  best.patchIndex = patchIndex;
  best.object = object;
  best.st = st;
  best.geometricNormal = normalize(cross(e1, e2));
}

#endif

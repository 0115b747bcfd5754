// The ray against one micro-triangle. Needs ray.glsl and trace_bindings.glsl.
#ifndef FACET_RAYCAST_TRIANGLE_GLSL
#define FACET_RAYCAST_TRIANGLE_GLSL

// Möller-Trumbore; on a hit in [tMin, best.t) that the object does not pass
// over (its normal is e1 x e2, as the CPU's; hit_filter.glsl), records it
// with the grid step of the hit point (the steps of the corners
// interpolated).
void intersect_triangle(Ray ray, vec3 a, vec3 b, vec3 c, vec2 stepA, vec2 stepB, vec2 stepC, float rate,
                        uint patchIndex, uint object, inout Hit best) {
  vec3 e1 = b - a, e2 = c - a;
  vec3 p = cross(ray.direction, e2);
  float det = dot(e1, p);
  if (det == 0.0) return;
  float inverse = 1.0 / det;
  vec3 q = ray.origin - a;
  float wb = dot(q, p) * inverse;
  if (wb < 0.0 || wb > 1.0) return;
  vec3 r = cross(q, e1);
  float wc = dot(ray.direction, r) * inverse;
  if (wc < 0.0 || wb + wc > 1.0) return;
  float t = dot(e2, r) * inverse;
  if (t < ray.tMin || t >= best.t) return;
  vec2 st = ((1.0 - wb - wc) * stepA + wb * stepB + wc * stepC) / rate;
  if (passes_over(object, ray.direction, cross(e1, e2), patchIndex, st, t)) return;
  best.t = t;
  best.patchIndex = patchIndex;
  best.object = object;
  best.st = st;
  best.geometricNormal = normalize(cross(e1, e2));
}

#endif

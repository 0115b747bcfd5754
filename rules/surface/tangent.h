// The tangent field an anisotropic lobe is oriented by (docs/shading.md,
// "Anisotropy"): the surface's parametric derivative dP/ds made orthogonal to
// the shading normal n (Gram-Schmidt) and turned about n by the material's
// rotation (cos, sin). Where dP/ds vanishes or lies along n (a degenerate
// patch corner), dP/dt turned a quarter about n stands in, as ds x dt ~ n
// makes dt x n point along ds; where both fail, the arbitrary frame's.
// Needs rules/shading/microfacet.h.

FACET_FN vec3 surface_tangent(vec3 n, vec3 dp_ds, vec3 dp_dt, real cos_rotation, real sin_rotation) {
  vec3 t = dp_ds - n * dot(n, dp_ds);
  if (!(dot(t, t) > real(0))) t = cross(dp_dt, n);
  real length2 = dot(t, t);
  t = length2 > real(0) ? t * inversesqrt(length2) : frame_from_normal(n).t;
  return t * cos_rotation + cross(n, t) * sin_rotation;
}

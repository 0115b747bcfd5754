// The tangent field an anisotropic lobe is oriented by (docs/shading.md,
// "Anisotropy"): the surface's parametric derivative dP/ds made orthogonal to
// the shading normal n (Gram-Schmidt) and turned about n by the material's
// rotation (cos, sin). Where dP/ds vanishes or lies along n (a degenerate
// patch corner), dP/dt turned a quarter about n stands in, as ds x dt ~ n
// makes dt x n point along ds; where both fail, the arbitrary frame's.

#ifndef FACET_RULE_SURFACE_TANGENT
#define FACET_RULE_SURFACE_TANGENT

#include "rules/shading/microfacet.h"

FACET_FN vec3 surface_tangent(vec3 n, vec3 dp_ds, vec3 dp_dt, real cos_rotation, real sin_rotation) {
  vec3 t = dp_ds - n * dot(n, dp_ds);
  if (!(dot(t, t) > real(0))) t = cross(dp_dt, n);
  real length2 = dot(t, t);
  t = length2 > real(0) ? t * inversesqrt(length2) : frame_from_normal(n).t;
  return t * cos_rotation + cross(n, t) * sin_rotation;
}

// Where the surface has texture coordinates, glTF's tangent frame
// (KHR_materials_anisotropy): t along dP/du, and the rotation turning t
// towards the bitangent that points up the image, against dP/dv (glTF's v
// runs down the image), so that a mirrored layout turns the other way. dP/du
// and dP/dv are solved from the partials over the patch's (s, t); where the
// coordinates do not vary (or are absent, all zero), surface_tangent's
// parametric field.
FACET_FN vec3 texcoord_tangent(vec3 n, vec3 dp_ds, vec3 dp_dt, vec2 duv_ds, vec2 duv_dt, real cos_rotation,
                               real sin_rotation) {
  real det = duv_ds.x * duv_dt.y - duv_ds.y * duv_dt.x;
  if (det == real(0)) return surface_tangent(n, dp_ds, dp_dt, cos_rotation, sin_rotation);
  vec3 dp_du = (dp_ds * duv_dt.y - dp_dt * duv_ds.y) / det;
  vec3 dp_dv = (dp_dt * duv_ds.x - dp_ds * duv_dt.x) / det;
  real turn = dot(cross(n, dp_du), dp_dv) > real(0) ? -sin_rotation : sin_rotation;
  return surface_tangent(n, dp_du, -dp_dv, cos_rotation, turn);
}

#endif

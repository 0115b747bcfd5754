// The shading normal of a mesh rendered as authored, its corner normals
// (counter-clockwise from (0, 0), as the patch's points) interpolated
// bilinearly at patch-local (s, t) and normalized; the zero vector where they
// cancel.

#ifndef FACET_RULE_SURFACE_AUTHORED_NORMAL
#define FACET_RULE_SURFACE_AUTHORED_NORMAL

FACET_FN vec3 authored_normal(vec3 n00, vec3 n10, vec3 n11, vec3 n01, real s, real t) {
  vec3 n = (real(1) - s) * (real(1) - t) * n00 + s * (real(1) - t) * n10 + s * t * n11 + (real(1) - s) * t * n01;
  real size = length(n);
  return size > real(0) ? n / size : vec3(real(0));
}

#endif

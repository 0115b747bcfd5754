// Fresnel reflectance of an optically flat facet, cos_i = cosine between the
// incident direction and the facet normal. Derivations: docs/shading.md.

#ifndef FACET_RULE_SHADING_FRESNEL
#define FACET_RULE_SHADING_FRESNEL

#include "rules/math.h"

const int F_NONE = 0;  // F = 1: the bare microfacet term, as used for albedo
const int F_SCHLICK = 1;
const int F_DIELECTRIC = 2;
const int F_CONDUCTOR = 3;
const int F_BLENDER_METALLIC = 4;  // Blender Cycles' Principled metallic, not the course's

FACET_FN vec3 fresnel_schlick(vec3 f0, real cos_i) {
  real m = real(1) - clamp(cos_i, real(0), real(1));
  real m2 = sqr(m);
  return f0 + (vec3(real(1)) - f0) * (m2 * m2 * m);
}

// Unpolarized reflectance of a dielectric interface with relative index of
// refraction eta = n_transmitted / n_incident > 0.
FACET_FN real fresnel_dielectric(real eta, real cos_i) {
  real c = clamp(cos_i, real(0), real(1));
  real g2 = sqr(eta) - real(1) + sqr(c);
  if (g2 <= real(0)) return real(1);  // total internal reflection
  real g = sqrt(g2);
  real a = (g - c) / (g + c);
  real b = (c * (g + c) - real(1)) / (c * (g - c) + real(1));
  return real(0.5) * sqr(a) * (real(1) + sqr(b));
}

// Unpolarized reflectance of a conductor with complex index eta + i k per
// channel, written with real arithmetic only (GLSL has no complex type).
FACET_FN vec3 fresnel_conductor(vec3 eta, vec3 k, real cos_i) {
  real c = clamp(cos_i, real(0), real(1));
  real c2 = sqr(c);
  real s2 = real(1) - c2;
  vec3 eta2 = eta * eta;
  vec3 k2 = k * k;
  vec3 t0 = eta2 - k2 - vec3(s2);
  vec3 a2_plus_b2 = sqrt(t0 * t0 + real(4) * eta2 * k2);
  vec3 a = sqrt(max(real(0.5) * (a2_plus_b2 + t0), vec3(real(0))));
  vec3 t1 = a2_plus_b2 + vec3(c2);
  vec3 t2 = real(2) * c * a;
  vec3 rs = (t1 - t2) / (t1 + t2);
  vec3 t3 = c2 * a2_plus_b2 + vec3(sqr(s2));
  vec3 t4 = t2 * s2;
  vec3 rp = rs * (t3 - t4) / (t3 + t4);
  return real(0.5) * (rs + rp);
}

// Blender Cycles' Principled BSDF, metallic: the exact dielectric curve at
// index 1.5 rescaled to run from F(0) = f0 at normal incidence to 1 at
// grazing, F = f0 + (1 - f0) (F_d(cos_i) - F_d(1)) / (1 - F_d(1))
// (docs/shading.md, "Blender's metallic Fresnel").
FACET_FN vec3 fresnel_blender_metallic(vec3 f0, real cos_i) {
  real normal = fresnel_dielectric(real(1.5), real(1));
  real t = (fresnel_dielectric(real(1.5), cos_i) - normal) / (real(1) - normal);
  return f0 + (vec3(real(1)) - f0) * t;
}

#endif

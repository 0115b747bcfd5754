// What a punctual light delivers at a surface point and the shadow ray that
// decides whether it arrives (docs/rendering.md, "Shading"). Each backend fills
// PunctualLight from its own light record. Needs INFINITE_DISTANCE,
// a real +infinity (compute/raycast/common/ray.glsl; rules/language.h in C++).

#ifndef FACET_RULE_SHADING_LIGHTS
#define FACET_RULE_SHADING_LIGHTS

#include "rules/math.h"
#include "rules/shading/brdf.h"
#include "rules/shading/clearcoat.h"

// A punctual light: directional (along `direction`), else at `position`,
// a spot around `direction` when `spot`, with its cones as cosines.
struct PunctualLight {
  bool directional;
  bool spot;
  vec3 position;
  vec3 direction;
  vec3 color;  // c_light (docs/scene-format.md)
  real cos_inner;
  real cos_outer;
};

// glTF's spot profile (KHR_lights_punctual): a squared linear ramp in cos
// theta between the cones.
FACET_FN real spot_falloff(real cos_angle, real cos_inner, real cos_outer) {
  real t = (cos_angle - cos_outer) / max(cos_inner - cos_outer, real(1e-4));
  real ramp = clamp(t, real(0), real(1));
  return ramp * ramp;
}

// The light as `point` sees it: the unit direction towards it, how far it
// is, and its colour after the inverse-square falloff and the spot profile.
struct LightIncidence {
  vec3 direction;
  real distance;
  vec3 color;
};

FACET_FN LightIncidence light_incidence(PunctualLight light, vec3 point) {
  LightIncidence incidence;
  incidence.color = light.color;
  if (light.directional) {
    incidence.direction = -light.direction;
    incidence.distance = INFINITE_DISTANCE;
    return incidence;
  }
  vec3 offset = light.position - point;
  incidence.distance = length(offset);
  incidence.direction = offset / incidence.distance;
  incidence.color /= incidence.distance * incidence.distance;
  if (light.spot)
    incidence.color *= spot_falloff(dot(-incidence.direction, light.direction), light.cos_inner, light.cos_outer);
  return incidence;
}

// Light from l reaches a two-sided surface only from above both its shading
// and its geometric normal (both turned to face the eye).
FACET_FN bool above_surface(vec3 n, vec3 ng, vec3 l) { return dot(n, l) > real(0) && dot(ng, l) > real(0); }

// Whether the light has anything to deliver, before its shadow ray.
FACET_FN bool light_arrives(LightIncidence incidence, vec3 n, vec3 ng) {
  return above_surface(n, ng, incidence.direction) && incidence.color != vec3(real(0));
}

// The radiance towards v of a light of incident colour c_light from l:
// pi f(l, v) c_light (n.l), the specular lobe scaled by `specular_scale`
// (brdf_evaluate_scaled).
FACET_FN vec3 punctual_radiance(BrdfParams p, vec3 n, vec3 l, vec3 v, vec3 color, vec3 specular_scale) {
  return PI * brdf_evaluate_scaled(p, n, l, v, specular_scale) * color * dot(n, l);
}

// Shadow rays leave the hit point along the geometric normal and start their
// t range at the same offset: 1e-6 of the scene's diagonal, and clear of the
// root tolerance, since an accepted root may be off by tolerance / sin(angle)
// along the ray.
const real SHADOW_OFFSET_IN_DIAGONALS = real(1e-6);
const real SHADOW_OFFSET_IN_TOLERANCES = real(32);

FACET_FN real shadow_ray_offset(real scene_diagonal, real root_tolerance) {
  return max(SHADOW_OFFSET_IN_DIAGONALS * scene_diagonal, SHADOW_OFFSET_IN_TOLERANCES * root_tolerance);
}

FACET_FN vec3 shadow_ray_origin(vec3 point, vec3 ng, real offset) { return point + offset * ng; }

#endif

// Where a path goes on from a vertex of a transmissive material, and what it
// carries there (docs/rendering.md, "Transmission and absorption"): the
// material is f = f_r + (1 - transmission) c_diff / pi + transmission f_t,
// its dielectric lobes (rules/shading/dielectric.h) and its diffuse lobe
// chosen by their weight; glTF's metallic mixes a metal over it, and its
// base colour tints f_t. continue_path (path_continuation.h) stays the rule
// of opaque materials.

#ifndef FACET_RULE_SHADING_TRANSMISSIVE_CONTINUATION
#define FACET_RULE_SHADING_TRANSMISSIVE_CONTINUATION

#include "rules/sampling/path_samples.h"
#include "rules/shading/absorption.h"
#include "rules/shading/brdf.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/dielectric.h"
#include "rules/shading/domain.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/lights.h"
#include "rules/shading/lobe_sampling.h"

// What a material adds to BrdfParams to transmit (glTF's
// KHR_materials_transmission, KHR_materials_volume, KHR_materials_ior).
struct TransmissionParams {
  real transmission;  // the share of the dielectric's diffuse base replaced by transmission, 0..1
  real ior;           // of the inside: the side the outward geometric normal points away from
  bool thin_walled;   // transmission without bending, through a wall of `thickness`
  vec3 sigma;         // absorption coefficient inside (absorption_coefficient)
  real thickness;     // thin-walled: the wall's thickness, for its absorption
};

// The BRDF of the reflection side that D(x) evaluates at a vertex seen from
// v `outside` or not: exact Fresnel of the interface's eta (total internal
// reflection inside), the diffuse base scaled by 1 - transmission, and
// glTF's mix(dielectric, metal, metallic) with the metal's F(0) the base
// colour (KHR_materials_transmission: transmission is the dielectric's
// alone). f0 keeps the base colour, which also tints what is transmitted; a
// material without one (a facet material) gives 1 and metallic 0.
FACET_FN BrdfParams transmissive_brdf_params(BrdfParams p, TransmissionParams t, bool outside, vec3 base,
                                             real metallic) {
  p.f_model = F_DIELECTRIC;
  real eta = transmissive_eta(t.ior, t.thin_walled, outside);
  p.eta = vec3(eta, eta, eta);
  p.f0 = base;
  p.metallic = metallic;
  p.diffuse = p.diffuse * (real(1) - t.transmission);
  return p;
}

// The share of light the interface transmits of what its dielectric does
// not reflect, for p as transmissive_brdf_params gives it: none of the
// metal's share.
FACET_FN real dielectric_transmission(BrdfParams p, TransmissionParams t) {
  return t.transmission * (real(1) - p.metallic);
}

// Whether no shadow ray from a vertex can reach the environment: v lies
// inside a solid, a transmissive material that is no thin wall seen from the
// inside of a surface that every ray from inside crosses (`sealed`,
// scenes/scene_geometry.h's sealsInside), and glass blocks shadow rays. D(x)
// then draws no environment pairs there: each would be blocked. Lights are
// still tried, for one may stand inside.
FACET_FN bool environment_sealed_off(bool transmissive, TransmissionParams t, bool outside, bool sealed) {
  return sealed && transmissive && !t.thin_walled && !outside;
}

// Probability of the diffuse lobe: its albedo against the dielectric lobes'
// energy at normal incidence, within [0.1, 0.9] when both are present.
FACET_FN real transmissive_diffuse_probability(BrdfParams p, TransmissionParams t) {
  real diffuse = luminance(p.diffuse);
  if (diffuse <= real(0)) return real(0);
  InterfaceSplit split = interface_split(p.eta.x, real(1), dielectric_transmission(p, t));
  real dielectric = split.reflect + split.transmit;
  if (dielectric <= real(0)) return real(1);
  return clamp(diffuse / (diffuse + dielectric), real(0.1), real(0.9));
}

struct TransmissiveContinuation {
  vec3 direction;
  vec3 weight;       // zero where the path ends
  bool transmitted;  // through the surface: the path changes medium (unless thin-walled)
  int lobe;          // PATH_LOBE_*, for the path's limits per lobe kind
};

// The lobe kind of continue_path's continuation for u seen from v about n: the
// coat's and the specular lobe's shares of u.x are glossy (sample_brdf_lobes).
FACET_FN int opaque_continuation_lobe(BrdfParams p, vec3 n, vec3 v, vec2 u) {
  real p_coat = coat_lobe_probability(p, v);
  if (p_coat > real(0)) {
    if (u.x < p_coat) return PATH_LOBE_GLOSSY;
    u = base_lobes_u(p_coat, u);
  }
  // A sheen's share takes the cosine sampler: diffuse.
  real p_sheen = sheen_lobe_probability(p, n, v);
  if (p_sheen > real(0)) {
    if (u.x < p_sheen) return PATH_LOBE_DIFFUSE;
    u = base_lobes_u(p_sheen, u);
  }
  return u.x < specular_lobe_probability(p) ? PATH_LOBE_GLOSSY : PATH_LOBE_DIFFUSE;
}

// p as transmissive_brdf_params gives it (p.eta.x the interface's eta); u as
// continue_path's, u_interface picks reflection or transmission
// (path_interface_u). A transmission carries the tint p.f0, and through a
// thin wall its Beer-Lambert factor over thickness / cos, cos inside the
// wall; `specular_scale` (energy compensation) weighs the dielectric lobes,
// reflection and transmission alike.
FACET_FN TransmissiveContinuation continue_path_transmissive(BrdfParams p, TransmissionParams t, vec3 n, vec3 ng,
                                                             vec3 v, vec3 specular_scale, vec2 u, real u_interface) {
  TransmissiveContinuation c;
  c.direction = vec3(real(0));
  c.weight = vec3(real(0));
  c.transmitted = false;
  c.lobe = PATH_LOBE_DIFFUSE;
  real p_diffuse = transmissive_diffuse_probability(p, t);
  real transmission = dielectric_transmission(p, t);
  bool diffuse = u.x < p_diffuse;
  vec2 v_u = diffuse ? vec2(min(u.x / p_diffuse, BELOW_ONE), u.y)
                     : vec2(min((u.x - p_diffuse) / (real(1) - p_diffuse), BELOW_ONE), u.y);
  if (!diffuse) {
    DielectricSample s = sample_dielectric(p.alpha, p.eta.x, transmission, t.thin_walled, n, ng, v, v_u, u_interface);
    c.direction = s.direction;
    c.transmitted = s.transmitted;
    c.lobe = s.transmitted ? PATH_LOBE_TRANSMISSION : PATH_LOBE_GLOSSY;
    if (s.weight <= real(0)) return c;
    if (s.transmitted) {
      // No other lobe reaches this direction: the weight is the dielectric's alone.
      c.weight = p.f0 * specular_scale * (s.weight / (real(1) - p_diffuse));
      if (t.thin_walled) c.weight *= beer_lambert(t.sigma, t.thickness / max(s.cos_inside, COS_EPSILON));
      return c;
    }
    if (p_diffuse <= real(0) && p.metallic == real(0)) {
      c.weight = specular_scale * s.weight;
      return c;
    }
  } else {
    c.direction = sample_direction(SAMPLE_COSINE, p, n, v, v_u);
    if (!above_surface(n, ng, c.direction)) return c;
  }
  // The reflection side is reached by both lobes, and a metal's share lies in
  // f, not in the dielectric's weight: f |n.l| over their mixed density.
  real pdf = p_diffuse * direction_pdf(SAMPLE_COSINE, p, n, c.direction, v) +
             (real(1) - p_diffuse) * dielectric_pdf(p.alpha, p.eta.x, transmission, n, c.direction, v);
  if (!(pdf > real(0))) return c;
  c.weight = brdf_evaluate_scaled(p, n, c.direction, v, specular_scale) * (dot(n, c.direction) / pdf);
  return c;
}

#endif

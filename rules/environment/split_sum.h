// The split sum of the prefiltered method (Karis 2013; the corrections are in
// docs/rendering.md, "Prefiltered: the split sum").

#ifndef FACET_RULE_ENVIRONMENT_SPLIT_SUM
#define FACET_RULE_ENVIRONMENT_SPLIT_SUM

#include "rules/math.h"
#include "rules/shading/brdf.h"
#include "rules/shading/thin_film.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/domain.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/sheen.h"

// Levels are spaced evenly in perceptual roughness sqrt(alpha): level i of
// `levels` has alpha = (i / (levels - 1))^2, level 0 is the map itself.
FACET_FN real prefiltered_level(real alpha, int levels) {
  return sqrt(clamp(alpha, real(0), real(1))) * real(levels - 1);
}

FACET_FN real prefiltered_level_alpha(int level, int levels) { return sqr(real(level) / real(levels - 1)); }

// Where the levels are read: the lobe's dominant direction, r bent towards
// n by alpha (Lagarde & de Rousiers 2014, as in Filament).
FACET_FN vec3 split_sum_direction(vec3 n, vec3 v, real alpha) {
  vec3 r = reflect(-v, n);
  real a = clamp(alpha, real(0), real(1));
  return normalize(r * (real(1) - a) + n * a);
}

// specular = prefiltered radiance x (F0 scale + F90 bias) x specular_scale,
// diffuse = c_diff x irradiance / pi. specular_scale is energy
// compensation's factor (dfg.h; Fdez-Aguera 2019's form), vec3(1) without
// it. F90 is Fresnel's grazing limit (0 only for a dielectric of index 1, no
// interface), written as the limit: lavapipe reassociates F evaluated near
// the horizon into 0. Under the BRDF's horizon policy (n.v <= COS_EPSILON)
// nothing is reflected, as with the sampled method.
// The specular lobe's albedo from the table's entry: F0 scale + F90 bias of
// the base; a thin film's F taken at n.v over the lobe's whole albedo, mixed
// in by the iridescence factor (docs/shading.md, "Iridescence").
FACET_FN vec3 split_sum_albedo(BrdfParams p, real nv, vec2 dfg) {
  bool dielectric = p.f_model == F_DIELECTRIC;
  vec3 f90 =
      vec3(dielectric && p.eta.x == real(1) ? real(0) : real(1), dielectric && p.eta.y == real(1) ? real(0) : real(1),
           dielectric && p.eta.z == real(1) ? real(0) : real(1));
  vec3 albedo = base_fresnel_F(p, real(1)) * dfg.x + f90 * dfg.y;
  if (!has_film(p)) return albedo;
  vec3 film = thin_film_fresnel(nv, p.iridescence_ior, p.iridescence_thickness, base_fresnel_F(p, real(1)));
  return mix(albedo, film * (dfg.x + dfg.y), p.iridescence);
}

FACET_FN vec3 split_sum(BrdfParams p, real nv, vec3 prefiltered, vec2 dfg, vec3 irradiance_over_pi,
                        vec3 specular_scale) {
  if (nv <= COS_EPSILON) return vec3(real(0));
  vec3 specular = prefiltered * split_sum_albedo(p, nv, dfg) * specular_scale;
  if (!has_sheen(p)) return specular + p.diffuse * irradiance_over_pi;
  // Under a sheen (docs/shading.md, "Sheen"): the specular lobe's light
  // arrives about the mirror direction, at n.l = n.v; the diffuse lobe's
  // over the hemisphere; the broad sheen's own as the irradiance.
  real e_v = sheen_albedo(p, nv);
  return specular * (real(1) - max_component(p.sheen_color) * min(e_v, real(1))) +
         p.diffuse * irradiance_over_pi * sheen_diffuse_scale(p, e_v) +
         p.sheen_color * (e_v / max(e_v, real(1))) * irradiance_over_pi;
}

// The split sum under a clear coat (docs/shading.md, "Clear coat"): the
// coat's lobe from the levels at its alpha read about its normal n_c
// (prefiltered_coat) and its (GGX, correlated Smith) table at n_c.v
// (dfg_coat), F(0) = 0.04 and F90 = 1; the base's lobes as split_sum gives
// them, times the coat's transmittance at n_c.v on the way out and on the
// way in: at the mirror direction, n_c.v again, for the specular lobe; for
// the diffuse lobe the cosine-weighted mean of the coat's Fresnel,
// F0 + (1 - F0) / 21.
FACET_FN vec3 coated_split_sum(BrdfParams p, real nv, vec3 prefiltered, vec2 dfg, vec3 irradiance_over_pi,
                               vec3 specular_scale, real nv_coat, vec3 prefiltered_coat, vec2 dfg_coat) {
  BrdfParams specular_only = p;
  specular_only.diffuse = vec3(real(0));
  vec3 specular = split_sum(specular_only, nv, prefiltered, dfg, irradiance_over_pi, specular_scale);
  vec3 diffuse = nv <= COS_EPSILON ? vec3(real(0)) : p.diffuse * irradiance_over_pi;
  if (has_sheen(p)) diffuse *= sheen_diffuse_scale(p, sheen_albedo(p, nv));
  real out_coat = coat_transmittance(p, nv_coat);
  real in_diffuse = real(1) - p.clearcoat * (COAT_F0 + (real(1) - COAT_F0) / real(21));
  vec3 coat =
      nv_coat <= COS_EPSILON ? vec3(real(0)) : prefiltered_coat * (p.clearcoat * (COAT_F0 * dfg_coat.x + dfg_coat.y));
  return (specular * out_coat + diffuse * in_diffuse) * out_coat + coat;
}

// Where the prefiltered method reads its levels and tables at a shading
// point: for the base, along its (bent) lobe at its isotropic-equivalent
// alpha; under a clear coat, for the coat too, about the coat's normal.
// Nothing is read where n.v is under the horizon policy's cutoff: the lobe
// may not even exist there.
struct SplitSumLookups {
  bool visible;
  real nv;
  real alpha;
  vec3 lobe;
  bool coated;
  real nv_coat;
  real coat_alpha;
  vec3 coat_lobe;
};

FACET_FN SplitSumLookups split_sum_lookups(BrdfParams p, vec3 n, vec3 v) {
  SplitSumLookups l;
  l.nv = dot(n, v);
  l.visible = l.nv > COS_EPSILON;
  l.alpha = isotropic_equivalent_alpha(p);
  l.lobe = n;
  l.coated = p.clearcoat != real(0);
  l.nv_coat = real(0);
  l.coat_alpha = p.clearcoat_alpha;
  l.coat_lobe = n;
  if (!l.visible) return l;
  l.lobe = split_sum_direction(anisotropic_bent_normal(p, n, v), v, l.alpha);
  if (!l.coated) return l;
  l.nv_coat = dot(p.clearcoat_normal, v);
  l.coat_lobe = split_sum_direction(p.clearcoat_normal, v, l.coat_alpha);
  return l;
}

// The split sum from what was read at `l`: the base's prefiltered radiance,
// DFG pair and irradiance, and (read only where l.coated) the coat's.
FACET_FN vec3 environment_split_sum(BrdfParams p, SplitSumLookups l, vec3 prefiltered, vec2 dfg,
                                    vec3 irradiance_over_pi, vec3 specular_scale, vec3 prefiltered_coat,
                                    vec2 dfg_coat) {
  if (!l.coated) return split_sum(p, l.nv, prefiltered, dfg, irradiance_over_pi, specular_scale);
  return coated_split_sum(p, l.nv, prefiltered, dfg, irradiance_over_pi, specular_scale, l.nv_coat,
                          prefiltered_coat, dfg_coat);
}

#endif

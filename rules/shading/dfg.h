// The split sum's DFG tables, their grid and their integrals
// (docs/rendering.md, "Prefiltered: the split sum"), and the
// multiple-scattering factor they give.

#ifndef FACET_RULE_SHADING_DFG
#define FACET_RULE_SHADING_DFG

#include "rules/math.h"
#include "rules/sampling/low_discrepancy.h"
#include "rules/shading/brdf.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/lobe_sampling.h"
#include "rules/shading/sheen.h"

// The two integrals for one sample l of the specular lobe (F = 1), weighted
// by n.l / pdf: scale multiplies F(0), bias is added, so that F(0) scale +
// bias = integral of f_spec (n.l) for Schlick's F.
FACET_FN vec2 dfg_sample_weight(real specular_value, real nl, real pdf, real vh) {
  if (pdf <= real(0) || nl <= real(0)) return vec2(real(0));
  real w = specular_value * nl / pdf;
  real fc = pow(real(1) - clamp(vh, real(0), real(1)), real(5));
  return vec2(w * (real(1) - fc), w * fc);
}

// Entry (i, j) of a size x size table sits at n.v = (i + 1) / size and
// sqrt(alpha) = j / (size - 1): n.v = 1 and alpha = 1 are entries, and the
// first column stays clear of n.v = 0, where E(n.v) drops to 0 faster than
// any column spacing follows. Lookups are bilinear at dfg_grid_position,
// clamped to the table.
FACET_FN real dfg_grid_nv(int i, int size) { return real(i + 1) / real(size); }

FACET_FN real dfg_grid_alpha(int j, int size) { return size > 1 ? sqr(real(j) / real(size - 1)) : real(0); }

FACET_FN vec2 dfg_grid_position(real nv, real alpha, int size) {
  real last = real(size - 1);
  return vec2(clamp(nv * real(size) - real(1), real(0), last), sqrt(clamp(alpha, real(0), real(1))) * last);
}

// One entry: (scale, bias) at n.v = nv and roughness alpha for the
// (d_model, g_model) pair with F = 1 (Schlick's with f0 = 1), over `samples`
// Hammersley points of the lobe's own technique.
FACET_FN vec2 dfg_integrals(int d_model, int g_model, real nv, real alpha, int samples) {
  BrdfParams p;
  p.d_model = d_model;
  p.g_model = g_model;
  p.f_model = F_SCHLICK;
  p.alpha = alpha;
  p.f0 = vec3(real(1));
  p.eta = vec3(real(1));
  p.k = vec3(real(0));
  p.metallic = real(0);
  p.diffuse = vec3(real(0));
  p.anisotropy = real(0);
  p.tangent = vec3(real(1), real(0), real(0));
  p.clearcoat = real(0);
  p.clearcoat_alpha = real(0);
  vec3 n = vec3(real(0), real(0), real(1));
  p.clearcoat_normal = n;
  p.sheen_color = vec3(real(0));
  p.sheen_alpha = real(0);
  p.sheen_albedo_near = vec4(real(0));
  p.sheen_albedo_far = vec4(real(0));
  p.iridescence = real(0);
  p.iridescence_ior = real(1);
  p.iridescence_thickness = real(0);
  vec3 v = vec3(sqrt(max(real(1) - nv * nv, real(0))), real(0), nv);
  int technique = specular_technique(p);
  vec2 sum = vec2(real(0));
  for (int k = 0; k < samples; ++k) {
    vec3 l = sample_direction(technique, p, n, v, hammersley_point(k, samples));
    real pdf = direction_pdf(technique, p, n, l, v);
    sum += dfg_sample_weight(brdf_terms(p, n, l, v).specular.x, l.z, pdf, real(0.5) * length(l + v));
  }
  return sum / real(samples);
}

// One entry of the sheen's albedo table (sheen.h): E(n.v) of its lobe for
// color 1 and alpha `alpha` over `samples` Hammersley points of the cosine
// sampler, as (E, 0). The lobe is broad and has no visible-normal sampler;
// D-proportional normals would weigh grazing microfacets by 1 / (n.m).
FACET_FN vec2 sheen_albedo_entry(real nv, real alpha, int samples) {
  vec3 n = vec3(real(0), real(0), real(1));
  vec3 v = vec3(sqrt(max(real(1) - nv * nv, real(0))), real(0), nv);
  real sum = real(0);
  for (int k = 0; k < samples; ++k) {
    vec3 l = sample_cosine_hemisphere(hammersley_point(k, samples));
    sum += sheen_lobe(alpha, n, l, v) * PI;  // f (n.l) / (n.l / pi)
  }
  return vec2(sum / real(samples), real(0));
}

// Four of a sheen's albedo knots (sheen.h), from knot `first` on.
FACET_FN vec4 sheen_albedo_knots(real alpha, int first, int samples) {
  return vec4(sheen_albedo_entry(sheen_knot_mu(first), alpha, samples).x,
              sheen_albedo_entry(sheen_knot_mu(first + 1), alpha, samples).x,
              sheen_albedo_entry(sheen_knot_mu(first + 2), alpha, samples).x,
              sheen_albedo_entry(sheen_knot_mu(first + 3), alpha, samples).x);
}

// Multiple-scattering compensation of the specular lobe (Turquin 2019, after
// Kulla & Conty 2017): f_ms = f_ss (1 + F0 (1 - E) / E), where E = scale +
// bias is the lobe's albedo for F = 1 at the view's n.v (docs/shading.md,
// "Energy compensation"). Returns the factor on f_ss.
FACET_FN vec3 energy_compensation(vec3 f0, vec2 dfg) {
  real e = dfg.x + dfg.y;
  if (e <= real(0)) return vec3(real(1));
  return vec3(real(1)) + f0 * ((real(1) - e) / e);
}

// The factor on material p's specular lobe, from its (D, G) table's entry
// `dfg` at the view's n.v and p's alpha. F0 is Fresnel at normal incidence:
// f0 for Schlick's F, what the other models give there.
FACET_FN vec3 specular_compensation(BrdfParams p, vec2 dfg) { return energy_compensation(fresnel_F(p, real(1)), dfg); }

// Which of a compensated material's tables, from its first, is read at a
// hit seen from v outside or not: a transmissive material has two glass
// tables, its interface seen from outside and from inside.
FACET_FN int compensation_table(int first, bool transmissive, bool outside) {
  return (transmissive && !outside) ? first + 1 : first;
}

// The factor on material p's specular lobe from its table's entry at the
// view's n.v. A transmissive material's reflection and transmission take
// the same factor, 1 / E of its glass table, so that a clear interface
// keeps all it receives: energy_compensation with F0 = 1. glTF's metal
// share of it (p.metallic) loses what a metal loses, not what the
// interface does, so the factor falls to 1 with it rather than lend the
// metal the interface's.
FACET_FN vec3 material_compensation(BrdfParams p, bool transmissive, vec2 entry) {
  if (!transmissive) return specular_compensation(p, entry);
  return mix(energy_compensation(vec3(real(1)), entry), vec3(real(1)), p.metallic);
}

#endif

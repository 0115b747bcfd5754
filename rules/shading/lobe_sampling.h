// One BRDF sample across a material's lobes (the base's two, a sheen's and a
// clear coat's), and its density
// (docs/rendering.md, "Sampled").

#ifndef FACET_RULE_SHADING_LOBE_SAMPLING
#define FACET_RULE_SHADING_LOBE_SAMPLING

#include "rules/shading/brdf.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/microfacet.h"
#include "rules/shading/sheen.h"

FACET_FN real luminance(vec3 c) { return real(0.2126) * c.x + real(0.7152) * c.y + real(0.0722) * c.z; }

// Probability of choosing the specular lobe: its share of the lobes' albedo
// at normal incidence, kept within [0.1, 0.9] when both are present so that
// neither lobe is starved.
FACET_FN real specular_lobe_probability(BrdfParams p) {
  real specular = luminance(fresnel_F(p, real(1)));
  real diffuse = luminance(p.diffuse);
  if (diffuse <= real(0)) return real(1);
  if (specular <= real(0)) return real(0);
  return clamp(specular / (specular + diffuse), real(0.1), real(0.9));
}

// The microfacet technique a material samples its specular lobe with: GGX's
// visible normals where D is GGX, else D-proportional normals.
FACET_FN int specular_technique(BrdfParams p) { return p.d_model == D_GGX ? SAMPLE_GGX_VISIBLE : SAMPLE_D; }

// The largest real below 1 that float holds, for coordinates rescaled into
// [0, 1).
const real BELOW_ONE = real(0.99999994039535522461);

// Probability of choosing the coat's lobe (clearcoat.h) before the base's:
// the coat's reflectance c F(n_c.v) against what it lets through to the
// base's lobes at normal incidence, kept within [0.1, 0.9] when both are
// present. 0 without a coat, which leaves the base's choice as it was.
FACET_FN real coat_lobe_probability(BrdfParams p, vec3 v) {
  if (p.clearcoat == real(0)) return real(0);
  real coat = p.clearcoat * coat_fresnel(dot(p.clearcoat_normal, v));
  real base = (real(1) - coat) * (luminance(fresnel_F(p, real(1))) + luminance(p.diffuse));
  if (base <= real(0)) return real(1);
  return clamp(coat / (coat + base), real(0.1), real(0.9));
}

// u with u.x, past the coat's share p_coat, stretched back to [0, 1) for the
// base's choice.
FACET_FN vec2 base_lobes_u(real p_coat, vec2 u) {
  return vec2(min((u.x - p_coat) / (real(1) - p_coat), BELOW_ONE), u.y);
}

// Probability of choosing the sheen's lobe (sheen.h; the cosine sampler
// about n) before the base's two: its albedo max(color) min(E(n.v), 1)
// against what it leaves them at normal incidence, kept within [0.1, 0.9]
// when both are present. 0 without a sheen.
FACET_FN real sheen_lobe_probability(BrdfParams p, vec3 n, vec3 v) {
  if (!has_sheen(p)) return real(0);
  real sheen = max_component(p.sheen_color) * min(sheen_albedo(p, dot(n, v)), real(1));
  real base = (real(1) - sheen) * (luminance(fresnel_F(p, real(1))) + luminance(p.diffuse));
  if (base <= real(0)) return real(1);
  return clamp(sheen / (sheen + base), real(0.1), real(0.9));
}

// u.x picks the lobe and, stretched back to [0, 1) over the lobe's share, is
// also the first coordinate of the direction within it: each lobe then
// draws a stratified subset of a stratified point set, where a separate
// lobe dimension would hand it a random one. Below a coat: a sheen's lobe
// first, then the base's two.
FACET_FN vec3 sample_base_lobes(BrdfParams p, vec3 n, vec3 v, vec2 u) {
  real p_sheen = sheen_lobe_probability(p, n, v);
  if (p_sheen > real(0)) {
    if (u.x < p_sheen) return sample_direction(SAMPLE_COSINE, p, n, v, vec2(min(u.x / p_sheen, BELOW_ONE), u.y));
    u = base_lobes_u(p_sheen, u);
  }
  real p_spec = specular_lobe_probability(p);
  if (u.x < p_spec) return sample_direction(specular_technique(p), p, n, v, vec2(min(u.x / p_spec, BELOW_ONE), u.y));
  return sample_direction(SAMPLE_COSINE, p, n, v, vec2(min((u.x - p_spec) / (real(1) - p_spec), BELOW_ONE), u.y));
}

FACET_FN real base_lobes_pdf(BrdfParams p, vec3 n, vec3 l, vec3 v) {
  real p_spec = specular_lobe_probability(p);
  real pdf = real(0);
  if (p_spec > real(0)) pdf += p_spec * direction_pdf(specular_technique(p), p, n, l, v);
  if (p_spec < real(1)) pdf += (real(1) - p_spec) * direction_pdf(SAMPLE_COSINE, p, n, l, v);
  real p_sheen = sheen_lobe_probability(p, n, v);
  if (p_sheen > real(0)) pdf = p_sheen * direction_pdf(SAMPLE_COSINE, p, n, l, v) + (real(1) - p_sheen) * pdf;
  return pdf;
}

// The coat's lobe takes the first share of u.x, its visible normals about n_c.
FACET_FN vec3 sample_brdf_lobes(BrdfParams p, vec3 n, vec3 v, vec2 u) {
  real p_coat = coat_lobe_probability(p, v);
  if (p_coat == real(0)) return sample_base_lobes(p, n, v, u);
  if (u.x < p_coat)
    return sample_direction(SAMPLE_GGX_VISIBLE, coat_lobe_params(p), p.clearcoat_normal, v,
                            vec2(min(u.x / p_coat, BELOW_ONE), u.y));
  return sample_base_lobes(p, n, v, base_lobes_u(p_coat, u));
}

FACET_FN real brdf_lobes_pdf(BrdfParams p, vec3 n, vec3 l, vec3 v) {
  real p_coat = coat_lobe_probability(p, v);
  if (p_coat == real(0)) return base_lobes_pdf(p, n, l, v);
  return p_coat * direction_pdf(SAMPLE_GGX_VISIBLE, coat_lobe_params(p), p.clearcoat_normal, l, v) +
         (real(1) - p_coat) * base_lobes_pdf(p, n, l, v);
}

#endif

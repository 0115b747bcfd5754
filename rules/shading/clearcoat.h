// A clear coat over the base BRDF (KHR_materials_clearcoat; docs/shading.md,
// "Clear coat"), and the whole material's BRDF with it.
//
// The coat is a dielectric of index 1.5 (F0 = 0.04) with glTF's specular
// lobe: GGX D, height-correlated Smith G, Schlick's F at v.h, about the coat
// normal n_c and scaled by the strength c. Light reaches the base through the
// coat and leaves through it again, so the base is weighted by
//   (1 - c F(n_c.v)) (1 - c F(n_c.l)),
// the glTF layering's factor (1 - c F(n_c.v)) applied on both crossings: the
// product keeps f(l, v) = f(v, l) and, as each factor alone, never adds
// energy.

#ifndef FACET_RULE_SHADING_CLEARCOAT
#define FACET_RULE_SHADING_CLEARCOAT

#include "rules/shading/brdf.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/microfacet.h"
#include "rules/shading/sheen.h"

// ((1.5 - 1) / (1.5 + 1))^2
const real COAT_F0 = real(0.04);

FACET_FN real coat_fresnel(real cos_i) { return fresnel_schlick(vec3(COAT_F0), cos_i).x; }

// The coat as a lobe of its own: BrdfParams of a bare GGX specular lobe of
// p's coat roughness, to evaluate and sample about p.clearcoat_normal.
FACET_FN BrdfParams coat_lobe_params(BrdfParams p) {
  BrdfParams c;
  c.d_model = D_GGX;
  c.g_model = G_SMITH_GGX_CORRELATED;
  c.f_model = F_SCHLICK;
  c.alpha = p.clearcoat_alpha;
  c.f0 = vec3(COAT_F0);
  c.eta = vec3(real(1));
  c.k = vec3(real(0));
  c.metallic = real(0);
  c.diffuse = vec3(real(0));
  c.anisotropy = real(0);
  c.tangent = p.tangent;
  c.clearcoat = real(0);
  c.clearcoat_alpha = real(0);
  c.clearcoat_normal = p.clearcoat_normal;
  c.sheen_color = vec3(real(0));
  c.sheen_alpha = real(0);
  c.sheen_albedo_near = vec4(real(0));
  c.sheen_albedo_far = vec4(real(0));
  c.iridescence = real(0);
  c.iridescence_ior = real(1);
  c.iridescence_thickness = real(0);
  return c;
}

// What the coat leaves of light crossing it at cos_i to n_c.
FACET_FN real coat_transmittance(BrdfParams p, real cos_i) { return real(1) - p.clearcoat * coat_fresnel(cos_i); }

// The coat's own reflection c f_coat(l, v), zero below its horizon.
FACET_FN vec3 coat_evaluate(BrdfParams p, vec3 l, vec3 v) {
  return p.clearcoat * brdf_terms(coat_lobe_params(p), p.clearcoat_normal, l, v).specular;
}

// f(l, v) with the base's specular lobe scaled per channel by
// `specular_scale`: vec3(1) is the course's single-scattering model, bit for
// bit; energy compensation's factor (rules/shading/dfg.h) restores what it
// loses. The coat is not compensated: its smooth lobes lose little. A sheen
// lies on the base, under the coat (sheen.h).
FACET_FN vec3 brdf_evaluate_scaled(BrdfParams p, vec3 n, vec3 l, vec3 v, vec3 specular_scale) {
  BrdfTerms t = brdf_terms(p, n, l, v);
  vec3 base = t.specular * specular_scale + t.diffuse;
  if (has_sheen(p)) base = sheen_over(p, n, l, v, base);
  if (p.clearcoat == real(0)) return base;
  vec3 nc = p.clearcoat_normal;
  return base * (coat_transmittance(p, dot(nc, v)) * coat_transmittance(p, dot(nc, l))) + coat_evaluate(p, l, v);
}

// The whole material's f(l, v): the base, under its coat where it has one.
FACET_FN vec3 brdf_evaluate(BrdfParams p, vec3 n, vec3 l, vec3 v) {
  return brdf_evaluate_scaled(p, n, l, v, vec3(real(1)));
}

#endif

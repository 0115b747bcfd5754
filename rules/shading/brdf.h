// The base BRDF
//   f(l, v) = F(v.h) G(l, v, h) D(h) / (4 (n.l)(n.v)) + c_diff / pi
// for any choice of D, G and F; a clear coat over it is
// rules/shading/clearcoat.h, which has the whole material's brdf_evaluate.

#ifndef FACET_RULE_SHADING_BRDF
#define FACET_RULE_SHADING_BRDF

#include "rules/math.h"
#include "rules/shading/domain.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/microfacet.h"
#include "rules/shading/thin_film.h"

// Which fields are read depends on the models: f0 for F_SCHLICK, eta for
// F_DIELECTRIC (per channel, so dispersion is possible), eta and k for
// F_CONDUCTOR. alpha is the microfacet alpha, not perceptual roughness.
// metallic in [0, 1] is glTF's metallic share of a transmissive material,
// a metal of F(0) = f0 mixed over its dielectric interface (F_DIELECTRIC
// only, docs/shading.md, "Transmission"): 0 is the bare interface (and its
// code path, bit for bit).
// anisotropy in [0, 1] is KHR_materials_anisotropy's strength: 0 is the
// isotropic lobe (and its code path, bit for bit); above, alpha_t along
// `tangent` (made orthogonal to n where used) is mix(alpha, 1, strength^2).
// clearcoat in [0, 1] is KHR_materials_clearcoat's strength: 0 is the bare
// base (and its code path, bit for bit); above, a GGX lobe of microfacet
// alpha clearcoat_alpha about clearcoat_normal (the normal before any normal
// map) lies over the base (clearcoat.h). sheen_color 0 is no sheen (and the
// base's code path, bit for bit); above, a Charlie lobe of sheen_alpha lies
// between the base and any coat, its directional albedo E(mu) given by 8
// knots (sheen.h). iridescence in [0, 1] is KHR_materials_iridescence's
// factor: 0 is the bare base (and its code path, bit for bit); above, F is
// mixed toward a thin film's of index iridescence_ior and thickness
// iridescence_thickness (nm) over the base (thin_film.h).
struct BrdfParams {
  int d_model;
  int g_model;
  int f_model;
  real alpha;
  vec3 f0;
  vec3 eta;
  vec3 k;
  real metallic;
  vec3 diffuse;
  real anisotropy;
  vec3 tangent;
  real clearcoat;
  real clearcoat_alpha;
  vec3 clearcoat_normal;
  vec3 sheen_color;
  real sheen_alpha;
  vec4 sheen_albedo_near;
  vec4 sheen_albedo_far;
  real iridescence;
  real iridescence_ior;
  real iridescence_thickness;
};

// The isotropic alpha that stands for p's lobe where a table is indexed by
// one roughness (the split sum's levels and DFG, energy compensation): alpha
// itself, or for an anisotropic lobe the mean of alpha_t and alpha_b, whose
// isotropic albedo is the closest simple match (docs/shading.md,
// "Anisotropy").
FACET_FN real isotropic_equivalent_alpha(BrdfParams p) {
  if (p.anisotropy == real(0)) return p.alpha;
  vec2 a = anisotropic_alpha(effective_alpha(p.alpha), p.anisotropy);
  return real(0.5) * (a.x + a.y);
}

// Every factor of one evaluation; all zero under the horizon policy.
struct BrdfTerms {
  vec3 value;  // specular + diffuse
  vec3 specular;
  vec3 diffuse;
  real D;
  real G;
  vec3 F;
};

// F of p's base, without any film.
FACET_FN vec3 base_fresnel_F(BrdfParams p, real cos_i) {
  switch (p.f_model) {
    case F_SCHLICK:
      return fresnel_schlick(p.f0, cos_i);
    case F_DIELECTRIC: {
      vec3 F = vec3(fresnel_dielectric(p.eta.x, cos_i), fresnel_dielectric(p.eta.y, cos_i),
                    fresnel_dielectric(p.eta.z, cos_i));
      // glTF: mix(dielectric, metal, metallic), the metal's F Schlick's.
      if (p.metallic != real(0)) F = mix(F, fresnel_schlick(p.f0, cos_i), p.metallic);
      return F;
    }
    case F_CONDUCTOR:
      return fresnel_conductor(p.eta, p.k, cos_i);
    case F_BLENDER_METALLIC:
      return fresnel_blender_metallic(p.f0, cos_i);
  }
  return vec3(real(1));
}

// Whether p's F has a thin film: a film of no thickness is no film.
FACET_FN bool has_film(BrdfParams p) { return p.iridescence != real(0) && p.iridescence_thickness > real(0); }

// F of p at cos_i to the facet normal: the base's, mixed toward its thin
// film's by the iridescence factor (KHR_materials_iridescence), the film
// lying on a base of the base's own F at normal incidence.
FACET_FN vec3 fresnel_F(BrdfParams p, real cos_i) {
  vec3 F = base_fresnel_F(p, cos_i);
  if (!has_film(p)) return F;
  vec3 film = thin_film_fresnel(cos_i, p.iridescence_ior, p.iridescence_thickness, base_fresnel_F(p, real(1)));
  return mix(F, film, p.iridescence);
}

// n, l, v: unit vectors; l points to the light, v to the viewer.
FACET_FN BrdfTerms brdf_terms(BrdfParams p, vec3 n, vec3 l, vec3 v) {
  BrdfTerms t;
  t.value = vec3(real(0));
  t.specular = vec3(real(0));
  t.diffuse = vec3(real(0));
  t.D = real(0);
  t.G = real(0);
  t.F = vec3(real(0));
  real nl = dot(n, l);
  real nv = dot(n, v);
  if (nl <= COS_EPSILON || nv <= COS_EPSILON) return t;
  // |l + v| >= n.l + n.v > 2 COS_EPSILON, so h is well defined. v.h is taken
  // as |l + v| / 2, which equals l.h exactly and keeps f(l, v) = f(v, l)
  // bit for bit in the Fresnel and G terms.
  vec3 l_plus_v = l + v;
  real len = length(l_plus_v);
  vec3 h = l_plus_v / len;
  real vh = real(0.5) * len;
  real nh = dot(n, h);
  real alpha = effective_alpha(p.alpha);
  if (p.anisotropy == real(0)) {
    t.D = microfacet_D(p.d_model, alpha, nh, sin2_between(n, h));
    t.G = microfacet_G(p.g_model, alpha, nl, nv, nh, vh);
  } else {
    Frame f = tangent_frame(n, p.tangent);
    vec2 a = anisotropic_alpha(alpha, p.anisotropy);
    t.D = microfacet_D_anisotropic(p.d_model, a, to_local(f, h));
    t.G = microfacet_G_anisotropic(p.g_model, a, to_local(f, l), to_local(f, v), nh, vh);
  }
  t.F = fresnel_F(p, vh);
  t.specular = t.F * (t.D * t.G / (real(4) * nl * nv));
  t.diffuse = p.diffuse * INV_PI;
  t.value = t.specular + t.diffuse;
  return t;
}

#endif

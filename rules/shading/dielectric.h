// A rough dielectric interface: GGX reflection and Walter et al. 2007's
// microfacet BTDF, the choice between them by exact Fresnel, and their
// densities (docs/shading.md, "Transmission"). Directions are world-space unit
// vectors with n facing v; eta = n_l / n_v, the index on l's side of the
// interface over the index on v's side. The smooth limit is the domain's
// ALPHA_MIN (effective_alpha), not a separate delta case.

#ifndef FACET_RULE_SHADING_DIELECTRIC
#define FACET_RULE_SHADING_DIELECTRIC

#include "rules/math.h"
#include "rules/sampling/low_discrepancy.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/domain.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/lights.h"
#include "rules/shading/microfacet.h"

// eta across the surface of a closed object whose inside has index `ior`,
// seen from v outside (the side the outward normal points to) or inside.
FACET_FN real interface_eta(real ior, bool outside) { return outside ? ior : real(1) / ior; }

// eta across a transmissive material's surface seen from v outside or not: a
// thin wall's one interface of its own index on either side, else
// interface_eta.
FACET_FN real transmissive_eta(real ior, bool thin_walled, bool outside) {
  return thin_walled ? ior : interface_eta(ior, outside);
}

// l below the facet of normal m (v.m > 0) by Snell's law, eta = n_l / n_v;
// vec3(0) under total internal reflection (pbrt-v4, Refract).
FACET_FN vec3 refract_through(vec3 v, vec3 m, real eta) {
  real c = dot(v, m);
  real sin2_t = (real(1) - sqr(c)) / sqr(eta);
  if (sin2_t >= real(1)) return vec3(real(0));
  real cos_t = sqrt(real(1) - sin2_t);
  return (c / eta - cos_t) * m - v / eta;
}

// Transmission without bending through a thin wall: the reflection of v
// about m mirrored through the tangent plane of n.
FACET_FN vec3 thin_wall_direction(vec3 n, vec3 v, vec3 m) {
  vec3 r = reflect(-v, m);
  return r - real(2) * dot(n, r) * n;
}

// Smith's height-correlated G for one direction on each side (Heitz 2014
// uses the same form for transmission as for reflection).
FACET_FN real dielectric_G(real alpha, real nl, real nv) {
  return real(1) / (real(1) + smith_lambda(D_GGX, alpha, abs(nl)) + smith_lambda(D_GGX, alpha, abs(nv)));
}

// f |n.l| / pdf of a direction reached through a visible normal of v, per
// unit of the energy the facet sends there: G2 / G1(v) (Heitz 2018, eq. 19).
FACET_FN real visible_normal_weight(real alpha, real nl, real nv) {
  return dielectric_G(alpha, nl, nv) / smith_G1(D_GGX, alpha, nv);
}

// The generalized half vector of a transmission pair, on n's side
// (Walter et al. 2007, eq. 16); vec3(0) where l = -v leaves it undefined.
FACET_FN vec3 transmission_half_vector(vec3 n, vec3 l, vec3 v, real eta) {
  vec3 h = v + eta * l;
  real len2 = dot(h, h);
  if (len2 <= sqr(COS_EPSILON)) return vec3(real(0));
  h = h * inversesqrt(len2);
  return dot(n, h) < real(0) ? -h : h;
}

// The radiance BTDF f_t(l, v) for l below and v above the surface, with
// (1 - F) and without the transmission factor (Walter et al. 2007, eq. 21,
// eta_o = n_v = 1 in units of v's side): generalized reciprocity is
// f_t(l, v; eta) eta^2 = f_t(v, l; 1 / eta).
FACET_FN real dielectric_btdf(real alpha_in, real eta, vec3 n, vec3 l, vec3 v) {
  real nl = dot(n, l);
  real nv = dot(n, v);
  if (nv <= COS_EPSILON || nl >= -COS_EPSILON) return real(0);
  vec3 m = transmission_half_vector(n, l, v, eta);
  real vm = dot(v, m);
  real lm = dot(l, m);
  if (vm <= real(0) || lm >= real(0)) return real(0);
  real alpha = effective_alpha(alpha_in);
  real D = microfacet_D(D_GGX, alpha, dot(n, m), sin2_between(n, m));
  real F = fresnel_dielectric(eta, vm);
  real denom = sqr(eta * lm + vm);
  return abs(lm) * vm * (real(1) - F) * dielectric_G(alpha, nl, nv) * D / (abs(nl) * nv * denom);
}

// Density of l under GGX's visible normals of v refracted through m:
// D_v(m) |dm/dl| with |dm/dl| = eta^2 |l.m| / (eta l.m + v.m)^2
// (Walter et al. 2007, eq. 17).
FACET_FN real dielectric_transmission_pdf(real alpha_in, real eta, vec3 n, vec3 l, vec3 v) {
  real nv = dot(n, v);
  if (nv <= COS_EPSILON || dot(n, l) >= real(0)) return real(0);
  vec3 m = transmission_half_vector(n, l, v, eta);
  real vm = dot(v, m);
  real lm = dot(l, m);
  if (vm <= real(0) || lm >= real(0)) return real(0);
  real alpha = effective_alpha(alpha_in);
  real pdf_m = ggx_visible_normal_pdf(alpha, nv, vm, dot(n, m), sin2_between(n, m));
  return pdf_m * sqr(eta) * abs(lm) / sqr(eta * lm + vm);
}

// Density of l reflected about GGX's visible normals of v.
FACET_FN real dielectric_reflection_pdf(real alpha_in, vec3 n, vec3 l, vec3 v) {
  if (dot(n, l) <= real(0)) return real(0);
  vec3 m = normalize(l + v);
  real alpha = effective_alpha(alpha_in);
  return ggx_visible_normal_pdf(alpha, dot(n, v), dot(v, m), dot(n, m), sin2_between(n, m)) /
         (real(4) * abs(dot(v, m)));
}

// The interface at a visible normal: the energy it reflects (F) and the
// energy its transmission lobe carries ((1 - F) times the transmission
// factor); reflection is chosen with probability reflect / (reflect + transmit).
struct InterfaceSplit {
  real reflect;
  real transmit;
};

FACET_FN InterfaceSplit interface_split(real eta, real vm, real transmission) {
  InterfaceSplit s;
  s.reflect = fresnel_dielectric(eta, vm);
  s.transmit = transmission * (real(1) - s.reflect);
  return s;
}

FACET_FN real reflect_probability(InterfaceSplit s) {
  real total = s.reflect + s.transmit;
  return total > real(0) ? s.reflect / total : real(1);
}

// One sample of the dielectric lobes f_r + transmission f_t of a smooth or
// rough interface (diffuse excluded): visible normal m from u, then
// reflection or transmission by u_interface against the split. weight is
// f |n.l| / pdf with the radiance BTDF, so a transmission divides by eta^2;
// thin-walled transmission goes straight through (no eta^2, no bending).
struct DielectricSample {
  vec3 direction;
  real weight;  // 0: no sample (a direction on the wrong side)
  bool transmitted;
  real cos_inside;  // thin-walled: cosine of the refracted ray inside the wall
};

FACET_FN DielectricSample sample_dielectric(real alpha_in, real eta, real transmission, bool thin_walled, vec3 n,
                                            vec3 ng, vec3 v, vec2 u, real u_interface) {
  DielectricSample s;
  s.direction = vec3(real(0));
  s.weight = real(0);
  s.transmitted = false;
  s.cos_inside = real(1);
  real alpha = effective_alpha(alpha_in);
  Frame f = frame_from_normal(n);
  vec3 m = from_local(f, sample_ggx_visible_normal(to_local(f, v), alpha, u));
  real vm = dot(v, m);
  real nv = dot(n, v);
  if (vm <= real(0) || nv <= COS_EPSILON) return s;
  InterfaceSplit split = interface_split(eta, vm, transmission);
  real total = split.reflect + split.transmit;
  s.transmitted = u_interface * total >= split.reflect;
  if (!s.transmitted) {
    s.direction = reflect(-v, m);
    if (!above_surface(n, ng, s.direction)) return s;
  } else if (thin_walled) {
    s.direction = thin_wall_direction(n, v, m);
    if (!above_surface(-n, -ng, s.direction)) return s;
    s.cos_inside = sqrt(max(real(1) - (real(1) - sqr(vm)) / sqr(eta), real(0)));
  } else {
    s.direction = refract_through(v, m, eta);
    if (!above_surface(-n, -ng, s.direction)) return s;
  }
  s.weight = total * visible_normal_weight(alpha, dot(n, s.direction), nv);
  if (s.transmitted && !thin_walled) s.weight /= sqr(eta);
  return s;
}

// The densities of sample_dielectric, for l on either side (thick interface).
FACET_FN real dielectric_pdf(real alpha, real eta, real transmission, vec3 n, vec3 l, vec3 v) {
  if (dot(n, l) > real(0)) {
    vec3 m = normalize(l + v);
    return reflect_probability(interface_split(eta, dot(v, m), transmission)) *
           dielectric_reflection_pdf(alpha, n, l, v);
  }
  vec3 m = transmission_half_vector(n, l, v, eta);
  if (m == vec3(real(0))) return real(0);
  return (real(1) - reflect_probability(interface_split(eta, dot(v, m), transmission))) *
         dielectric_transmission_pdf(alpha, eta, n, l, v);
}

// One entry of a glass albedo table: E(n.v) of a clear interface's
// dielectric lobes (transmission 1, eta = n_l / n_v; thin-walled or not), the
// energy its single-scattering reflections and transmissions keep of what
// arrives, over `samples` Hammersley points of v's visible normals, each
// sending F of its energy by reflection and 1 - F through (without the
// radiance's 1 / eta^2, which moves energy into a smaller solid angle and
// loses none), as (E, 0). A smooth interface keeps 1 (docs/shading.md,
// "Energy compensation of glass").
FACET_FN vec2 glass_albedo_entry(real nv, real alpha_in, real eta, bool thin_walled, int samples) {
  vec3 n = vec3(real(0), real(0), real(1));
  vec3 v = vec3(sqrt(max(real(1) - nv * nv, real(0))), real(0), nv);
  real alpha = effective_alpha(alpha_in);
  real sum = real(0);
  for (int k = 0; k < samples; ++k) {
    vec3 m = sample_ggx_visible_normal(v, alpha, hammersley_point(k, samples));
    real vm = dot(v, m);
    if (vm <= real(0)) continue;
    real F = fresnel_dielectric(eta, vm);
    vec3 r = reflect(-v, m);
    if (r.z > real(0)) sum += F * visible_normal_weight(alpha, r.z, nv);
    vec3 t = thin_walled ? thin_wall_direction(n, v, m) : refract_through(v, m, eta);
    if (t.z < real(0)) sum += (real(1) - F) * visible_normal_weight(alpha, t.z, nv);
  }
  return vec2(sum / real(samples), real(0));
}

#endif

// Importance sampling of the BRDF and the matching densities.
//
// A technique maps u in [0,1)^2 to a direction l for a given v. The pdf is
// the density of l over the whole sphere of directions (solid angle), so it
// integrates to 1 there; a sampled l under the horizon is a valid sample on
// which the BRDF is 0.

#ifndef FACET_RULE_SHADING_BRDF_SAMPLING
#define FACET_RULE_SHADING_BRDF_SAMPLING

#include "rules/math.h"
#include "rules/shading/brdf.h"
#include "rules/shading/domain.h"
#include "rules/shading/microfacet.h"

const int SAMPLE_COSINE = 0;       // cosine-weighted hemisphere (Lambert)
const int SAMPLE_D = 1;            // half vector with density D(m)(n.m), for d_model
const int SAMPLE_GGX_VISIBLE = 2;  // half vector from GGX's visible normals as seen from v

FACET_FN vec3 spherical_direction(real sin2_theta, real cos_theta, real phi) {
  real sin_theta = sqrt(max(sin2_theta, real(0)));
  return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

FACET_FN vec3 sample_cosine_hemisphere(vec2 u) {
  return spherical_direction(u.x, sqrt(real(1) - u.x), real(2) * PI * u.y);
}

// Local frame (n = z): m with density D(m)(n.m), by inverting the CDF of
// the polar angle. sin^2 is formed without 1 - cos^2 where the CDF allows.
FACET_FN vec3 sample_microfacet_normal(int model, real alpha, vec2 u) {
  real a2 = sqr(alpha);
  real cos2 = real(1);
  real sin2 = real(0);
  switch (model) {
    case D_GGX: {
      // tan^2 = alpha^2 u / (1 - u), multiplied through by cos^2.
      real denom = real(1) + (a2 - real(1)) * u.x;
      cos2 = (real(1) - u.x) / denom;
      sin2 = a2 * u.x / denom;
      break;
    }
    case D_BECKMANN: {
      // tan^2 = -alpha^2 ln(1 - u); u = 1 would be the horizon itself.
      real tan2 = -a2 * log(max(real(1) - u.x, real(1.0e-30)));
      cos2 = real(1) / (real(1) + tan2);
      sin2 = tan2 * cos2;
      break;
    }
    case D_BLINN_PHONG:
      // cos = u^(1 / (exponent + 2)).
      cos2 = pow(u.x, real(2) / (blinn_phong_exponent(alpha) + real(2)));
      sin2 = real(1) - cos2;
      break;
  }
  return spherical_direction(sin2, sqrt(cos2), real(2) * PI * u.y);
}

// Local frame: m with density D(m)(n.m) for the anisotropic D of roughness
// alpha = (alpha_t, alpha_b): GGX's and Beckmann's slopes scale with alpha
// (Heitz 2014, sec. 5.4), so the alpha = 1 sample stretched by alpha_t along
// x and alpha_b along y has the anisotropic density.
FACET_FN vec3 sample_microfacet_normal_anisotropic(int model, vec2 alpha, vec2 u) {
  vec3 m = sample_microfacet_normal(model, real(1), u);
  return normalize(vec3(alpha.x * m.x, alpha.y * m.y, m.z));
}

// Local frame: m from GGX's distribution of visible normals for v (v.z > 0),
// D_v(m) = G1(v) max(0, v.m) D(m) / (n.v), alpha = (alpha_t, alpha_b).
// Heitz 2018: stretch v to the alpha = 1 configuration, sample its visible
// normals there and stretch back; Dupuy & Benyoub 2023: at alpha = 1 they are
// a uniform spherical cap shifted by v.
FACET_FN vec3 sample_ggx_visible_normal_anisotropic(vec3 v, vec2 alpha, vec2 u) {
  vec3 v_std = normalize(vec3(alpha.x * v.x, alpha.y * v.y, v.z));
  real phi = real(2) * PI * u.x;
  real z = (real(1) - u.y) * (real(1) + v_std.z) - v_std.z;
  vec3 m_std = spherical_direction(real(1) - sqr(z), z, phi) + v_std;
  // m_std.z >= 0 by construction; at u.y = 1 the cap point can be -v_std
  // itself and m_std vanish. A floor on z turns that single point into n
  // (a change of measure 0, below D's own resolution elsewhere).
  return normalize(vec3(alpha.x * m_std.x, alpha.y * m_std.y, max(m_std.z, real(1.0e-10))));
}

FACET_FN vec3 sample_ggx_visible_normal(vec3 v, real alpha, vec2 u) {
  return sample_ggx_visible_normal_anisotropic(v, vec2(alpha, alpha), u);
}

FACET_FN real ggx_visible_normal_pdf(real alpha, real nv, real vm, real nm, real sin2_m) {
  if (nv <= COS_EPSILON) return real(0);
  return smith_G1(D_GGX, alpha, nv) * max(vm, real(0)) * microfacet_D(D_GGX, alpha, nm, sin2_m) / nv;
}

// The same for the anisotropic lobe, v and m in the tangent frame.
FACET_FN real ggx_visible_normal_pdf_anisotropic(vec2 alpha, vec3 v, real vm, vec3 m) {
  if (v.z <= COS_EPSILON) return real(0);
  return max(vm, real(0)) * microfacet_D_anisotropic(D_GGX, alpha, m) /
         ((real(1) + smith_lambda_anisotropic(D_GGX, alpha, v)) * v.z);
}

// World space: l for the given technique (l may fall under the horizon).
FACET_FN vec3 sample_direction(int technique, BrdfParams p, vec3 n, vec3 v, vec2 u) {
  if (technique == SAMPLE_COSINE) return from_local(frame_from_normal(n), sample_cosine_hemisphere(u));
  real alpha = effective_alpha(p.alpha);
  if (p.anisotropy != real(0)) {
    Frame g = tangent_frame(n, p.tangent);
    vec2 a = anisotropic_alpha(alpha, p.anisotropy);
    vec3 m = technique == SAMPLE_GGX_VISIBLE ? sample_ggx_visible_normal_anisotropic(to_local(g, v), a, u)
                                             : sample_microfacet_normal_anisotropic(p.d_model, a, u);
    return reflect(-v, from_local(g, m));
  }
  Frame f = frame_from_normal(n);
  vec3 m = technique == SAMPLE_GGX_VISIBLE ? sample_ggx_visible_normal(to_local(f, v), alpha, u)
                                           : sample_microfacet_normal(p.d_model, alpha, u);
  return reflect(-v, from_local(f, m));
}

// Density of l under sample_direction, per unit solid angle.
FACET_FN real direction_pdf(int technique, BrdfParams p, vec3 n, vec3 l, vec3 v) {
  if (technique == SAMPLE_COSINE) return max(dot(n, l), real(0)) * INV_PI;
  // The sampled normal m is the upper-hemisphere one of +-(l + v); the
  // Jacobian of reflection is dw_m / dw_l = 1 / (4 |v.m|). |l + v| at or
  // below COS_EPSILON counts as l = -v, reachable by no microfacet.
  vec3 l_plus_v = l + v;
  real len2 = dot(l_plus_v, l_plus_v);
  if (len2 <= sqr(COS_EPSILON)) return real(0);
  vec3 m = l_plus_v * inversesqrt(len2);
  if (dot(n, m) < real(0)) m = -m;
  real nm = dot(n, m);
  real vm = dot(v, m);
  real alpha = effective_alpha(p.alpha);
  real pdf_m;
  if (p.anisotropy != real(0)) {
    Frame g = tangent_frame(n, p.tangent);
    vec2 a = anisotropic_alpha(alpha, p.anisotropy);
    vec3 m_local = to_local(g, m);
    pdf_m = technique == SAMPLE_GGX_VISIBLE ? ggx_visible_normal_pdf_anisotropic(a, to_local(g, v), vm, m_local)
                                            : microfacet_D_anisotropic(p.d_model, a, m_local) * nm;
  } else {
    real sin2_m = sin2_between(n, m);
    pdf_m = technique == SAMPLE_GGX_VISIBLE ? ggx_visible_normal_pdf(alpha, dot(n, v), vm, nm, sin2_m)
                                            : microfacet_D(p.d_model, alpha, nm, sin2_m) * nm;
  }
  return pdf_m / (real(4) * abs(vm));
}

// The normal the split sum reads an anisotropic lobe about (docs/shading.md,
// "Anisotropy"): n bent towards v's component across b, the smoother
// direction, by a clamp(5 sqrt(alpha)) (Filament's bent reflection vector,
// after McAuley & Sloan 2015), Filament's anisotropy a = (alpha_t - alpha_b)
// / (alpha_t + alpha_b) taken from the lobe's two roughnesses: a lobe that
// the mapping leaves round (alpha = 1) is not bent. n where isotropic.
FACET_FN vec3 anisotropic_bent_normal(BrdfParams p, vec3 n, vec3 v) {
  if (p.anisotropy == real(0)) return n;
  Frame f = tangent_frame(n, p.tangent);
  vec3 across = cross(cross(f.b, v), f.b);
  real alpha = effective_alpha(p.alpha);
  vec2 a = anisotropic_alpha(alpha, p.anisotropy);
  real bend = (a.x - a.y) / (a.x + a.y) * clamp(real(5) * sqrt(alpha), real(0), real(1));
  vec3 bent = n * (real(1) - bend) + across * bend;
  real length2 = dot(bent, bent);
  return length2 > real(0) ? bent * inversesqrt(length2) : n;
}

#endif

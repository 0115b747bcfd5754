// Microfacet normal distributions D and shadowing-masking functions G. Formulas
// and their derivations: docs/shading.md.

#ifndef FACET_RULE_SHADING_MICROFACET
#define FACET_RULE_SHADING_MICROFACET

#include "rules/math.h"
#include "rules/shading/domain.h"

// Normal distribution ids. Smith G names its microsurface with the same ids.
const int D_GGX = 0;
const int D_BECKMANN = 1;
const int D_BLINN_PHONG = 2;

// Shadowing-masking ids.
const int G_IMPLICIT = 0;
const int G_COOK_TORRANCE = 1;
const int G_KELEMEN = 2;
const int G_SMITH_GGX = 3;
const int G_SMITH_GGX_CORRELATED = 4;
const int G_SMITH_BECKMANN = 5;
const int G_SMITH_BECKMANN_CORRELATED = 6;

// Walter et al. 2007: matching the Beckmann curvature at the peak,
// D_blinn(exponent) ~ D_beckmann(alpha) with exponent = 2 / alpha^2 - 2.
FACET_FN real blinn_phong_exponent(real alpha) { return real(2) / sqr(alpha) - real(2); }
FACET_FN real blinn_phong_alpha(real exponent) { return sqrt(real(2) / (exponent + real(2))); }

// ln(1 - x) for 0 <= x < 0.1 by its power series -sum x^k / k, k <= 16
// (truncation below 1e-17 relative). log(1 - x) would lose the digits of a
// small x when 1 - x is rounded, in float almost all of them.
FACET_FN real log_one_minus_small(real x) {
  real sum = real(1) / real(16);
  for (int k = 15; k >= 1; --k) sum = real(1) / real(k) + x * sum;
  return -x * sum;
}

// D(m) for a microfacet normal m with cos_m = n.m and sin2_m = |n x m|^2.
// Each is normalized: integral of D(m) (n.m) over the hemisphere is 1.
// D is 0 outside its support n.m > 0; Beckmann is cut to 0 where it falls
// below exp(-80) of its peak, before cos^4 could underflow in float.
FACET_FN real microfacet_D(int model, real alpha, real cos_m, real sin2_m) {
  if (cos_m <= real(0)) return real(0);
  real a2 = sqr(alpha);
  real c2 = sqr(cos_m);
  switch (model) {
    case D_GGX:
      // alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2), with cos^4 multiplied in so
      // that no tangent (and no 1 - cos^2 cancellation) appears.
      return a2 / (PI * sqr(a2 * c2 + sin2_m));
    case D_BECKMANN:
      if (sin2_m >= real(80) * c2 * a2) return real(0);
      return exp(-sin2_m / (c2 * a2)) / (PI * a2 * sqr(c2));
    case D_BLINN_PHONG: {
      // cos^e. Near the peak, where a large exponent magnifies the rounding
      // of cos, as exp((e/2) ln(1 - sin^2)) from the accurate sin^2.
      real exponent = blinn_phong_exponent(alpha);
      real power = sin2_m < real(0.1) ? exp(real(0.5) * exponent * log_one_minus_small(sin2_m)) : pow(cos_m, exponent);
      return (exponent + real(2)) * (real(0.5) * INV_PI) * power;
    }
  }
  return real(0);
}

// Smith's Lambda of the Beckmann microsurface for a direction at cos_v = c
// (clamped) and alpha_sin = alpha sin (the projected roughness times sin,
// sqrt(alpha_t^2 x^2 + alpha_b^2 y^2) when anisotropic; Heitz 2014, eq. 80):
// Lambda(a) = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = c / alpha_sin,
// with erfc(a) = exp(-a^2) t P(t), t = 1 / (1 + p a) from Abramowitz &
// Stegun 7.1.26 (absolute error <= 1.5e-7, so Lambda is within 7.5e-8).
// Written without a division by sin so that normal incidence is exact.
FACET_FN real beckmann_lambda(real c, real alpha_sin) {
  if (c >= real(6) * alpha_sin) return real(0);  // erfc(6) < 3e-17
  real a = c / alpha_sin;
  real t = real(1) / (real(1) + real(0.3275911) * a);
  real erfc_over_gauss =
      t * (real(0.254829592) +
           t * (real(-0.284496736) + t * (real(1.421413741) + t * (real(-1.453152027) + t * real(1.061405429)))));
  return max(real(0), real(0.5) * exp(-sqr(a)) * (real(1) / (a * sqrt(PI)) - erfc_over_gauss));
}

// GGX's Lambda (sqrt(1 + alpha^2 tan^2) - 1) / 2 for cos_v = c and a2s2 =
// alpha^2 sin^2 (alpha_t^2 x^2 + alpha_b^2 y^2 when anisotropic), rationalized
// so that a small alpha^2 tan^2 does not cancel.
FACET_FN real ggx_lambda(real c, real a2s2) { return a2s2 / (real(2) * c * (sqrt(sqr(c) + a2s2) + c)); }

// Smith's Lambda for the GGX or Beckmann microsurface (by D id), direction at
// cos_v = n.v (clamped to the horizon epsilon).
FACET_FN real smith_lambda(int surface, real alpha, real cos_v) {
  real c = max(cos_v, COS_EPSILON);
  real s2 = max(real(1) - sqr(c), real(0));
  if (surface == D_BECKMANN) return beckmann_lambda(c, alpha * sqrt(s2));
  return ggx_lambda(c, sqr(alpha) * s2);
}

FACET_FN real smith_G1(int surface, real alpha, real cos_v) {
  return real(1) / (real(1) + smith_lambda(surface, alpha, cos_v));
}

// G(l, v, h) for reflection: nl = n.l, nv = n.v, nh = n.h, vh = v.h = l.h,
// all positive (the caller applies the horizon policy).
FACET_FN real microfacet_G(int model, real alpha, real nl, real nv, real nh, real vh) {
  switch (model) {
    case G_IMPLICIT:
      return nl * nv;
    case G_COOK_TORRANCE:
      return min(real(1), real(2) * nh * min(nl, nv) / vh);
    case G_KELEMEN:
      return nl * nv / sqr(vh);
    case G_SMITH_GGX:
      return smith_G1(D_GGX, alpha, nl) * smith_G1(D_GGX, alpha, nv);
    case G_SMITH_GGX_CORRELATED:
      return real(1) / (real(1) + smith_lambda(D_GGX, alpha, nl) + smith_lambda(D_GGX, alpha, nv));
    case G_SMITH_BECKMANN:
      return smith_G1(D_BECKMANN, alpha, nl) * smith_G1(D_BECKMANN, alpha, nv);
    case G_SMITH_BECKMANN_CORRELATED:
      return real(1) / (real(1) + smith_lambda(D_BECKMANN, alpha, nl) + smith_lambda(D_BECKMANN, alpha, nv));
  }
  return real(0);
}

// Orthonormal frame with n as z axis (Duff et al. 2017, branch-free apart
// from the hemisphere sign).
struct Frame {
  vec3 t;
  vec3 b;
  vec3 n;
};

FACET_FN Frame frame_from_normal(vec3 n) {
  real s = n.z >= real(0) ? real(1) : real(-1);
  real a = real(-1) / (s + n.z);
  real b = n.x * n.y * a;
  Frame f;
  f.t = vec3(real(1) + s * sqr(n.x) * a, s * b, -s * n.x);
  f.b = vec3(b, s + sqr(n.y) * a, -n.y);
  f.n = n;
  return f;
}

FACET_FN vec3 to_local(Frame f, vec3 w) { return vec3(dot(w, f.t), dot(w, f.b), dot(w, f.n)); }
FACET_FN vec3 from_local(Frame f, vec3 w) { return w.x * f.t + w.y * f.b + w.z * f.n; }

// Anisotropy (docs/shading.md, "Anisotropy"). The frame of an anisotropic
// lobe: `tangent` made orthogonal to n (Gram-Schmidt), b = n x t; a tangent
// along n has no direction to offer, and the arbitrary frame stands in.
FACET_FN Frame tangent_frame(vec3 n, vec3 tangent) {
  vec3 t = tangent - n * dot(n, tangent);
  real length2 = dot(t, t);
  if (!(length2 > real(1.0e-12))) return frame_from_normal(n);
  Frame f;
  f.t = t * inversesqrt(length2);
  f.b = cross(n, f.t);
  f.n = n;
  return f;
}

// KHR_materials_anisotropy's roughnesses for strength s in [0, 1]:
// alpha_t = mix(alpha, 1, s^2) along the tangent, alpha_b = alpha.
FACET_FN vec2 anisotropic_alpha(real alpha, real strength) { return vec2(mix(alpha, real(1), sqr(strength)), alpha); }

// Anisotropic D for m = (t.m, b.m, n.m) in the tangent frame, roughness
// alpha = (alpha_t, alpha_b): with e = x^2 / alpha_t^2 + y^2 / alpha_b^2
// (= tan^2 cos^2 times the slope's quadratic form; Heitz 2014, eqs. 77, 80),
// GGX 1 / (pi alpha_t alpha_b (e + z^2)^2) and Beckmann exp(-e / z^2) /
// (pi alpha_t alpha_b z^4), each the isotropic formula at alpha_t = alpha_b.
// Blinn-Phong has no anisotropic form here (materials refuse the pairing).
FACET_FN real microfacet_D_anisotropic(int model, vec2 alpha, vec3 m) {
  if (m.z <= real(0)) return real(0);
  real c2 = sqr(m.z);
  real e = sqr(m.x / alpha.x) + sqr(m.y / alpha.y);
  if (model == D_GGX) return real(1) / (PI * alpha.x * alpha.y * sqr(e + c2));
  if (model == D_BECKMANN) {
    if (e >= real(80) * c2) return real(0);
    return exp(-e / c2) / (PI * alpha.x * alpha.y * sqr(c2));
  }
  return real(0);
}

// Smith's Lambda of the anisotropic GGX or Beckmann microsurface for w in the
// tangent frame: the isotropic Lambda with alpha^2 sin^2 replaced by
// alpha_t^2 x^2 + alpha_b^2 y^2 (Heitz 2014, eq. 80).
FACET_FN real smith_lambda_anisotropic(int surface, vec2 alpha, vec3 w) {
  real c = max(w.z, COS_EPSILON);
  real a2s2 = sqr(alpha.x * w.x) + sqr(alpha.y * w.y);
  if (surface == D_BECKMANN) return beckmann_lambda(c, sqrt(a2s2));
  return ggx_lambda(c, a2s2);
}

// G for l and v in the tangent frame; the G models without a microsurface
// (implicit, Cook-Torrance, Kelemen) do not depend on alpha.
FACET_FN real microfacet_G_anisotropic(int model, vec2 alpha, vec3 l, vec3 v, real nh, real vh) {
  if (model < G_SMITH_GGX) return microfacet_G(model, alpha.y, l.z, v.z, nh, vh);
  int surface = model >= G_SMITH_BECKMANN ? D_BECKMANN : D_GGX;
  real lambda_l = smith_lambda_anisotropic(surface, alpha, l);
  real lambda_v = smith_lambda_anisotropic(surface, alpha, v);
  if (model == G_SMITH_GGX || model == G_SMITH_BECKMANN)
    return real(1) / (real(1) + lambda_l) * (real(1) / (real(1) + lambda_v));
  return real(1) / (real(1) + lambda_l + lambda_v);
}

#endif

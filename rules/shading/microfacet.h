// Microfacet normal distributions D and shadowing-masking functions G. Formulas
// and their derivations: docs/shading.md.

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

// Smith's Lambda for the GGX or Beckmann microsurface (by D id), direction at
// cos_v = n.v (clamped to the horizon epsilon).
FACET_FN real smith_lambda(int surface, real alpha, real cos_v) {
  real c = max(cos_v, COS_EPSILON);
  real s2 = max(real(1) - sqr(c), real(0));
  if (surface == D_BECKMANN) {
    // Lambda(a) = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = cot / alpha,
    // with erfc(a) = exp(-a^2) t P(t), t = 1 / (1 + p a) from Abramowitz &
    // Stegun 7.1.26 (absolute error <= 1.5e-7, so Lambda is within 7.5e-8).
    // Written without a division by sin so that normal incidence is exact.
    real alpha_sin = alpha * sqrt(s2);
    if (c >= real(6) * alpha_sin) return real(0);  // erfc(6) < 3e-17
    real a = c / alpha_sin;
    real t = real(1) / (real(1) + real(0.3275911) * a);
    real erfc_over_gauss =
        t * (real(0.254829592) +
             t * (real(-0.284496736) + t * (real(1.421413741) + t * (real(-1.453152027) + t * real(1.061405429)))));
    return max(real(0), real(0.5) * exp(-sqr(a)) * (real(1) / (a * sqrt(PI)) - erfc_over_gauss));
  }
  // GGX: (sqrt(1 + alpha^2 tan^2) - 1) / 2, rationalized so that small
  // alpha^2 tan^2 does not cancel.
  real a2s2 = sqr(alpha) * s2;
  return a2s2 / (real(2) * c * (sqrt(sqr(c) + a2s2) + c));
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

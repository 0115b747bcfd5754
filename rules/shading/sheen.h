// Sheen (KHR_materials_sheen; docs/shading.md, "Sheen"): a Charlie lobe
// over the base, under any clear coat. Its sampling is lobe_sampling.h's
// and its albedo's entries dfg.h's.
//
// f = color D V / max(1, e) + base (1 - max(color) min(e, 1)), with glTF's
// Charlie D, the Charlie visibility V, and e the larger of the lobe's
// directional albedos E(n.v) and E(n.l) (sheen_layer).

#ifndef FACET_RULE_SHADING_SHEEN
#define FACET_RULE_SHADING_SHEEN

#include "rules/math.h"
#include "rules/shading/brdf.h"
#include "rules/shading/domain.h"

// The smallest sheen alpha (roughness 0.07): below it D's mass sits within a
// few degrees of the horizon, finer than the albedo's knots resolve.
const real SHEEN_MIN_ALPHA = real(0.0049);

// E(mu) of a material's sheen is its albedo table: an untextured material
// has one sheen roughness, so the table is one row of 8 knots (BrdfParams'
// sheen_albedo_near and _far, each sheen_albedo_entry in dfg.h) at mu_k =
// SHEEN_KNOT_MU0 + (1 - SHEEN_KNOT_MU0) (k / 7)^2, denser at grazing angles
// where E bends fastest, read linearly between them and held below mu_0.
const real SHEEN_KNOT_MU0 = real(0.02);

FACET_FN real sheen_knot_mu(int k) {
  real t = real(k) / real(7);
  return SHEEN_KNOT_MU0 + (real(1) - SHEEN_KNOT_MU0) * t * t * t;
}

FACET_FN bool has_sheen(BrdfParams p) { return p.sheen_color != vec3(real(0)); }

FACET_FN real sheen_alpha(real alpha) { return max(alpha, SHEEN_MIN_ALPHA); }

// A sheen whose roughness a texture sets per hit reads its knots from rows
// tabulated at SHEEN_ROWS alphas, read linearly between the two rows about
// the hit's (sheen_rows_at). The rows are spaced evenly in the fourth root
// of the alpha from SHEEN_MIN_ALPHA to 1, densest at the smooth end where E
// changes fastest: at 33 rows a knot read between rows is within 0.0022 of
// the knot tabulated at its own alpha.
const int SHEEN_ROWS = 33;

FACET_FN real sheen_row_root(real alpha) { return sqrt(sqrt(alpha)); }

// Row j's alpha.
FACET_FN real sheen_row_alpha(int j) {
  real low = sheen_row_root(SHEEN_MIN_ALPHA);
  real root = low + (real(1) - low) * real(j) / real(SHEEN_ROWS - 1);
  return sqr(sqr(root));
}

// The rows about a sheen of alpha `alpha`: the first, and the weight of
// the second.
struct SheenRows {
  int first;
  real weight;
};

FACET_FN SheenRows sheen_rows_at(real alpha) {
  real low = sheen_row_root(SHEEN_MIN_ALPHA);
  real position =
      clamp((sheen_row_root(sheen_alpha(alpha)) - low) / (real(1) - low), real(0), real(1)) * real(SHEEN_ROWS - 1);
  SheenRows rows;
  rows.first = min(int(position), SHEEN_ROWS - 2);
  rows.weight = position - real(rows.first);
  return rows;
}

FACET_FN real sheen_albedo(BrdfParams p, real mu) {
  real x =
      pow(clamp((mu - SHEEN_KNOT_MU0) / (real(1) - SHEEN_KNOT_MU0), real(0), real(1)), real(1) / real(3)) * real(7);
  int k = min(int(x), 6);
  real a = k < 4 ? p.sheen_albedo_near[k] : p.sheen_albedo_far[k - 4];
  real b = k < 3 ? p.sheen_albedo_near[k + 1] : p.sheen_albedo_far[k - 3];
  return mix(a, b, x - real(k));
}

// Estevez & Kulla 2017, eq. 2: D(m) = (2 + 1/alpha) sin^(1/alpha) / (2 pi),
// normalized like the other D's (integral of D (n.m) is 1).
FACET_FN real sheen_D(real alpha, real sin2_m) {
  real inv = real(1) / alpha;
  return (real(2) + inv) * pow(max(sin2_m, real(0)), real(0.5) * inv) * (real(0.5) * INV_PI);
}

// Estevez & Kulla 2017, sec. 3: the fitted L(x) = a / (1 + b x^c) + d x + e,
// its parameters blended between their alpha = 0 and alpha = 1 fits by
// (1 - alpha)^2, and Lambda(cos) = exp(L(cos)) below cos = 0.5, mirrored
// above it as exp(2 L(0.5) - L(1 - cos)).
FACET_FN real sheen_L(real x, real alpha) {
  real t = sqr(real(1) - alpha);
  real a = mix(real(21.5473), real(25.3245), t);
  real b = mix(real(3.82987), real(3.32435), t);
  real c = mix(real(0.19823), real(0.16801), t);
  real d = mix(real(-1.97760), real(-1.27393), t);
  real e = mix(real(-4.32054), real(-4.85967), t);
  return a / (real(1) + b * pow(x, c)) + d * x + e;
}

FACET_FN real sheen_lambda(real cos_i, real alpha) {
  real x = clamp(cos_i, real(0), real(1));
  if (x < real(0.5)) return exp(sheen_L(x, alpha));
  return exp(real(2) * sheen_L(real(0.5), alpha) - sheen_L(real(1) - x, alpha));
}

// D V for unit l and v about n, with V = 1 / (4 (n.l)(n.v) (1 + Lambda(v) +
// Lambda(l))), the height-correlated form; 0 under the horizon policy.
FACET_FN real sheen_lobe(real alpha, vec3 n, vec3 l, vec3 v) {
  real nl = dot(n, l);
  real nv = dot(n, v);
  if (nl <= COS_EPSILON || nv <= COS_EPSILON) return real(0);
  real a = sheen_alpha(alpha);
  vec3 h = normalize(l + v);
  real lambdas = real(1) + sheen_lambda(nv, a) + sheen_lambda(nl, a);
  return sheen_D(a, sin2_between(n, h)) / (real(4) * nl * nv * lambdas);
}

// The two parts of the layered f(l, v) given the albedos e_v = E(n.v) and
// e_l = E(n.l): the sheen's own reflection and the factor on the base.
// glTF's factor 1 - max(color) E(n.v) is taken at the larger of the two
// albedos (the specification's min form), which keeps f(l, v) = f(v, l);
// where the lobe's albedo goes above 1 (grazing, smooth sheen) the lobe is
// divided by it, so that the sheen alone and over a white base never adds
// energy (docs/shading.md, "Sheen").
struct SheenLayer {
  vec3 sheen;
  real base_scale;
};

FACET_FN real max_component(vec3 c) { return max(c.x, max(c.y, c.z)); }

FACET_FN SheenLayer sheen_layer(BrdfParams p, real lobe, real e_v, real e_l) {
  real e = max(e_v, e_l);
  SheenLayer layer;
  layer.sheen = p.sheen_color * (lobe / max(e, real(1)));
  layer.base_scale = real(1) - max_component(p.sheen_color) * min(e, real(1));
  return layer;
}

// The layering's factor on a diffuse base with l integrated out: the
// cosine-weighted mean of 1 - max(color) min(max(e_v, E(n.l)), 1), by the
// midpoint rule on 8 panels of n.l.
FACET_FN real sheen_diffuse_scale(BrdfParams p, real e_v) {
  real sum = real(0);
  for (int i = 0; i < 8; ++i) {
    real mu = (real(i) + real(0.5)) / real(8);
    sum += mu * min(max(e_v, sheen_albedo(p, mu)), real(1));
  }
  return real(1) - max_component(p.sheen_color) * sum * real(0.25);
}

// `base`, f(l, v) of the material below the sheen, under p's sheen.
FACET_FN vec3 sheen_over(BrdfParams p, vec3 n, vec3 l, vec3 v, vec3 base) {
  SheenLayer layer =
      sheen_layer(p, sheen_lobe(p.sheen_alpha, n, l, v), sheen_albedo(p, dot(n, v)), sheen_albedo(p, dot(n, l)));
  return base * layer.base_scale + layer.sheen;
}

#endif

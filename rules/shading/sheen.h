// Sheen (KHR_materials_sheen; docs/shading.md, "Sheen"): a Charlie lobe
// over the base, its albedo table's entries, the layering and the sampled
// lobe. Needs the rules of rules/shading/, lobe_sampling.h and
// low_discrepancy.h.
//
// f = color D V + base (1 - max(color) E), with glTF's Charlie D and the
// Charlie visibility V, and E the sheen's directional albedo (its table);
// the layering is written with both directions' albedos so that it stays
// reciprocal (sheen_layer).

// The smallest sheen alpha (roughness 0.07): below it D's mass sits within a
// few degrees of the horizon, finer than the albedo table's columns resolve.
const real SHEEN_MIN_ALPHA = real(0.0049);

// The albedo table's id where a DFG table holds a (D, G) pair
// (engine/ibl/prefiltered_environment.h): entries (E, 0) over the DFG grid,
// sqrt(alpha) being the sheen roughness.
const int SHEEN_ALBEDO_TABLE = 100;

struct SheenParams {
  vec3 color;  // KHR_materials_sheen's sheenColorFactor; 0 is no sheen
  real alpha;  // sheenRoughness^2
};

FACET_FN real sheen_alpha(real alpha) { return max(alpha, SHEEN_MIN_ALPHA); }

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

// The table's entry at (nv, alpha): the lobe's directional albedo for color
// 1 over `samples` Hammersley points of the cosine sampler, (E, 0).
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

// The two parts of the layered f(l, v) given the table's albedos e_v =
// E(n.v) and e_l = E(n.l): the sheen's own reflection and the factor on the
// base. glTF's factor 1 - max(color) E(n.v) is taken at the larger of the
// two albedos, which keeps f(l, v) = f(v, l); where the lobe's albedo goes
// above 1 (grazing, smooth sheen) the lobe is divided by it, so that the
// sheen alone and over a white base never adds energy (docs/shading.md).
struct SheenLayer {
  vec3 sheen;
  real base_scale;
};

FACET_FN SheenLayer sheen_layer(SheenParams s, real lobe, real e_v, real e_l) {
  real e = max(e_v, e_l);
  SheenLayer layer;
  layer.sheen = s.color * (lobe / max(e, real(1)));
  layer.base_scale = real(1) - max(s.color.x, max(s.color.y, s.color.z)) * min(e, real(1));
  return layer;
}

// The whole material's f(l, v) with its base's specular lobe scaled by
// `specular_scale` (brdf_evaluate_scaled), under a sheen: the base's own bits
// where the color is 0.
FACET_FN vec3 sheen_evaluate(BrdfParams p, SheenParams s, vec3 n, vec3 l, vec3 v, vec3 specular_scale, real e_v,
                             real e_l) {
  vec3 base = brdf_evaluate_scaled(p, n, l, v, specular_scale);
  if (s.color == vec3(real(0))) return base;
  SheenLayer layer = sheen_layer(s, sheen_lobe(s.alpha, n, l, v), e_v, e_l);
  return base * layer.base_scale + layer.sheen;
}

// Probability of sampling the sheen's lobe (the cosine sampler about n)
// before the base's: its albedo max(color) min(E(n.v), 1) against what it
// leaves the base's lobes at normal incidence, kept within [0.1, 0.9] when
// both are present. 0 without a sheen.
FACET_FN real sheen_lobe_probability(BrdfParams p, SheenParams s, real e_v) {
  if (s.color == vec3(real(0))) return real(0);
  real sheen = max(s.color.x, max(s.color.y, s.color.z)) * min(e_v, real(1));
  real base = (real(1) - sheen) * (luminance(fresnel_F(p, real(1))) + luminance(p.diffuse));
  if (base <= real(0)) return real(1);
  return clamp(sheen / (sheen + base), real(0.1), real(0.9));
}

// The sheen takes the first share of u.x, like the coat (sample_brdf_lobes).
FACET_FN vec3 sample_sheen_lobes(BrdfParams p, SheenParams s, vec3 n, vec3 v, real e_v, vec2 u) {
  real p_sheen = sheen_lobe_probability(p, s, e_v);
  if (p_sheen == real(0)) return sample_brdf_lobes(p, n, v, u);
  if (u.x < p_sheen) return sample_direction(SAMPLE_COSINE, p, n, v, vec2(min(u.x / p_sheen, BELOW_ONE), u.y));
  return sample_brdf_lobes(p, n, v, base_lobes_u(p_sheen, u));
}

FACET_FN real sheen_lobes_pdf(BrdfParams p, SheenParams s, vec3 n, vec3 l, vec3 v, real e_v) {
  real p_sheen = sheen_lobe_probability(p, s, e_v);
  if (p_sheen == real(0)) return brdf_lobes_pdf(p, n, l, v);
  return p_sheen * direction_pdf(SAMPLE_COSINE, p, n, l, v) + (real(1) - p_sheen) * brdf_lobes_pdf(p, n, l, v);
}

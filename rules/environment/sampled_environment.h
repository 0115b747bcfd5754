// The sampled method's estimator (docs/rendering.md, "Sampled"). Per camera
// sample, N pairs of one environment sample and one BRDF sample, each weighted
// by the power heuristic against the other technique's density. Drawing from
// the environment's distribution, and its density, are each backend's own (an
// alias table in texel buffers, or in vectors); the rest is here.

#ifndef FACET_RULE_ENVIRONMENT_SAMPLED_ENVIRONMENT
#define FACET_RULE_ENVIRONMENT_SAMPLED_ENVIRONMENT

#include "rules/sampling/mis.h"
#include "rules/sampling/random.h"
#include "rules/sampling/scrambled_net.h"
#include "rules/shading/brdf.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/lights.h"
#include "rules/shading/lobe_sampling.h"

// Pair `pair` of `pairs`: point `pair` of the scrambled net of (pixel,
// sample, seed) (scrambled_net.h), three groups of two dimensions: the
// texel as 32 bits and keep-or-alias, the position in the texel, the BRDF
// sample's lobe and direction (sample_brdf_lobes). Another seed scrambles
// independently, so that a reference does not share the numbers of the
// estimate it judges.
struct EnvironmentPair {
  uint texel_bits;
  vec3 environment_u;
  vec3 brdf_direction;
};

FACET_FN EnvironmentPair environment_pair(BrdfParams p, vec3 n, vec3 v, uint pixel, uint sample_index, uint seed,
                                          uint pair, uint pairs) {
  uvec2 texel = scrambled_point_bits(pixel, sample_index, seed, 0u, pair, pairs);
  vec2 position = scrambled_point(pixel, sample_index, seed, 1u, pair, pairs);
  vec2 direction = scrambled_point(pixel, sample_index, seed, 2u, pair, pairs);
  EnvironmentPair e;
  e.texel_bits = texel.x;
  e.environment_u = vec3(unit_from_bits(texel.y), position.x, position.y);
  e.brdf_direction = sample_brdf_lobes(p, n, v, direction);
  return e;
}

// One sample of either technique: its direction, its density and the other
// technique's density there.
struct MisSample {
  vec3 direction;
  real pdf;
  real other_pdf;
};

FACET_FN MisSample environment_technique_sample(BrdfParams p, vec3 n, vec3 v, vec3 l, real environment_pdf) {
  MisSample s;
  s.direction = l;
  s.pdf = environment_pdf;
  s.other_pdf = brdf_lobes_pdf(p, n, l, v);
  return s;
}

FACET_FN MisSample brdf_technique_sample(BrdfParams p, vec3 n, vec3 v, vec3 l, real environment_pdf) {
  MisSample s;
  s.direction = l;
  s.pdf = brdf_lobes_pdf(p, n, l, v);
  s.other_pdf = environment_pdf;
  return s;
}

// Whether the sample can carry light (before its shadow ray, if any).
FACET_FN bool mis_sample_arrives(MisSample s, vec3 n, vec3 ng) {
  return s.pdf > real(0) && above_surface(n, ng, s.direction);
}

// Its share of the estimate, unshadowed, for radiance `radiance` arriving
// from its direction: f L (n.l) w_MIS / pdf, over the `pairs` pairs, the
// specular lobe scaled by `specular_scale` (brdf_evaluate_scaled).
FACET_FN vec3 mis_sample_share(BrdfParams p, vec3 n, vec3 v, MisSample s, vec3 radiance, uint pairs,
                               vec3 specular_scale) {
  vec3 l = s.direction;
  return brdf_evaluate_scaled(p, n, l, v, specular_scale) * radiance * dot(n, l) *
         (power_heuristic(s.pdf, s.other_pdf) / s.pdf) / real(pairs);
}

#endif

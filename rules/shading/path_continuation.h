// Where a path goes on from a shaded vertex, and what it carries there
// (docs/rendering.md, "Paths"): a direction drawn from
// the whole material with sample_brdf_lobes, and the weight
// f(l, v) (n.l) / pdf(l) that multiplies the path's throughput. Both
// backends continue their paths with this one rule, so that they trace the
// same paths.

#ifndef FACET_RULE_SHADING_PATH_CONTINUATION
#define FACET_RULE_SHADING_PATH_CONTINUATION

#include "rules/shading/brdf.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/lights.h"
#include "rules/shading/lobe_sampling.h"

struct PathContinuation {
  vec3 direction;
  vec3 weight;  // zero where the path ends: below the surface, or no density
};

FACET_FN PathContinuation continue_path(BrdfParams p, vec3 n, vec3 ng, vec3 v, vec3 specular_scale, vec2 u) {
  PathContinuation c;
  c.direction = sample_brdf_lobes(p, n, v, u);
  c.weight = vec3(real(0));
  if (!above_surface(n, ng, c.direction)) return c;
  real pdf = brdf_lobes_pdf(p, n, c.direction, v);
  if (!(pdf > real(0))) return c;
  c.weight = brdf_evaluate_scaled(p, n, c.direction, v, specular_scale) * (dot(n, c.direction) / pdf);
  return c;
}

#endif

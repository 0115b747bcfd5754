// The preview's ground as the paths see it (docs/preview-stage.md, "The
// ground in the paths"): a shadow catcher that a continuation ray finds as
// the background B behind it, darkened by the share of the environment's
// light that the scene takes from the ground. Its environment slots are
// scaled so that they sum to B before their shadow rays: what arrives is
// then B times the ratio of the light that gets past the scene to the light
// offered, per channel, the composite's ratio at one vertex, in [0, B] and
// exactly B where no shadow ray is blocked. The path ends there, as at the
// background. Camera rays pass over it: the ground's own pixels are the
// composite of its two scenes.

#ifndef FACET_RULE_SHADING_SHADOW_CATCHER
#define FACET_RULE_SHADING_SHADOW_CATCHER

#include "rules/shading/brdf.h"

// The factor of the environment's slots, which hold `offered` before their
// shadow rays: B / offered per channel, 0 where nothing is offered.
FACET_FN vec3 catcher_slot_scale(vec3 background, vec3 offered) {
  vec3 scale;
  scale.x = offered.x > real(0) ? background.x / offered.x : real(0);
  scale.y = offered.y > real(0) ? background.y / offered.y : real(0);
  scale.z = offered.z > real(0) ? background.z / offered.z : real(0);
  return scale;
}

// The slot no shadow ray tests: B in a channel where the environment offers
// nothing to block, else 0.
FACET_FN vec3 catcher_unshadowed(vec3 background, vec3 offered) {
  vec3 rest;
  rest.x = offered.x > real(0) ? real(0) : background.x;
  rest.y = offered.y > real(0) ? real(0) : background.y;
  rest.z = offered.z > real(0) ? real(0) : background.z;
  return rest;
}

// The vertex a path leaves the catcher from: black (the ground has no
// specular lobe, a dielectric of index 1), so that it ends there.
FACET_FN BrdfParams catcher_path_params(BrdfParams p) {
  p.diffuse = vec3(real(0));
  return p;
}

// Whether a ray sees the catcher: continuation rays do (vertex >= 2), the
// camera ray (vertex 1) passes over it.
FACET_FN bool catcher_seen_at(uint vertex) { return vertex > uint(1); }

#endif

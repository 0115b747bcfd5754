// The shading model's numerical policy: where its parameters and directions
// are valid, derived in docs/shading.md ("Clamps and the domain").

#ifndef FACET_RULE_SHADING_DOMAIN
#define FACET_RULE_SHADING_DOMAIN

// Roughness alpha is clamped to [ALPHA_MIN, 1]: below ALPHA_MIN float can no
// longer resolve the lobe, above 1 the Blinn-Phong exponent turns negative.
const real ALPHA_MIN = real(1.0e-3);
// Directions l, v with n.l or n.v at or below COS_EPSILON count as under the
// horizon: every term of the BRDF is 0 there. This bounds all denominators
// away from 0 in float and double alike.
const real COS_EPSILON = real(1.0e-4);

FACET_FN real effective_alpha(real alpha) { return clamp(alpha, ALPHA_MIN, real(1)); }

#endif

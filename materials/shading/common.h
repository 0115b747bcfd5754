// Shared GLSL / C++ source: constants and the numerical policy of the shading
// model. Written in the common subset of both languages (see
// materials/shading.h and materials/shading.glsl): scalar type `real`,
// typed literals so the float instantiation really computes in float, no
// references, no constructors of structs. No include guard on purpose: C++
// includes this file once per real type, each time in its own namespace.

const real PI = real(3.14159265358979323846);
const real INV_PI = real(0.31830988618379067154);

// The policy below is derived in docs/shading.md ("Clamps and the domain").
// Roughness alpha is clamped to [ALPHA_MIN, 1]: below ALPHA_MIN float can no
// longer resolve the lobe, above 1 the Blinn-Phong exponent turns negative.
const real ALPHA_MIN = real(1.0e-3);
// Directions l, v with n.l or n.v at or below COS_EPSILON count as under the
// horizon: every term of the BRDF is 0 there. This bounds all denominators
// away from 0 in float and double alike.
const real COS_EPSILON = real(1.0e-4);

FACET_FN real sqr(real x) { return x * x; }

FACET_FN real effective_alpha(real alpha) { return clamp(alpha, ALPHA_MIN, real(1)); }

// sin^2 of the angle between two unit vectors via Lagrange's identity
// |a x b|^2; unlike 1 - (a.b)^2 it keeps full relative precision near 0,
// which is where narrow lobes are evaluated.
FACET_FN real sin2_between(vec3 a, vec3 b) {
  vec3 c = cross(a, b);
  return dot(c, c);
}

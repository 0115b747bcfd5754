// The constants and small identities every rule builds on. Written in the
// common subset of GLSL and C++ (rules/language.h says what that is).

#ifndef FACET_RULE_MATH
#define FACET_RULE_MATH

const real PI = real(3.14159265358979323846);
const real INV_PI = real(0.31830988618379067154);

FACET_FN real sqr(real x) { return x * x; }

// sin^2 of the angle between two unit vectors via Lagrange's identity
// |a x b|^2; unlike 1 - (a.b)^2 it keeps full relative precision near 0,
// which is where narrow lobes are evaluated.
FACET_FN real sin2_between(vec3 a, vec3 b) {
  vec3 c = cross(a, b);
  return dot(c, c);
}

#endif

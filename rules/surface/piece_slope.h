// When a ray crosses a piece of a patch at most once, so that one root of
// Newton's on the piece settles it (docs/rendering.md, "Conservative
// bounds"). The piece's bounds are taken in the frame of the plane through
// its corners: by Markov's inequality a cubic's derivative on an interval is
// at most 9 x its range over the interval, so the surface's height above
// that plane rises at most 9 x the bounds' thickness across their narrower
// side. A ray steeper to the plane than that meets the surface once at most;
// a flatter one, or a twisted piece whose corners span no plane, may meet it
// twice, and the piece is split.

#ifndef FACET_RULE_SURFACE_PIECE_SLOPE
#define FACET_RULE_SURFACE_PIECE_SLOPE

const real CUBIC_MARKOV = real(9);

// Thickness along the plane's normal, width the narrower extent across it.
FACET_FN real piece_slope_bound(real thickness, real width) {
  return width > real(0) ? CUBIC_MARKOV * thickness / width : INFINITE_DISTANCE;
}

// Whether a ray along `direction` is steeper to the plane of unit normal
// `normal` than `slope`.
FACET_FN bool steeper_than(vec3 direction, vec3 normal, real slope) {
  real along = dot(direction, normal);
  return abs(along) > slope * length(direction - along * normal);
}

#endif

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

// The frame of the plane through a piece's corner points (the middles of its
// control boxes at the four corners): its unit `normal`, and `along` the
// piece's s direction in that plane. False, with the axes' own frame, where
// the corners span no plane.
FACET_FN bool corner_plane(vec3 c00, vec3 c30, vec3 c03, vec3 c33, FACET_OUT(vec3) normal, FACET_OUT(vec3) along) {
  vec3 n = cross(c33 - c00, c03 - c30);
  vec3 u = (c30 - c00) + (c33 - c03);
  u -= dot(u, n) / max(dot(n, n), real(1e-30)) * n;
  bool planar = length(n) > real(0) && length(u) > real(0);
  normal = planar ? normalize(n) : vec3(real(0), real(0), real(1));
  along = planar ? normalize(u) : vec3(real(1), real(0), real(0));
  return planar;
}

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

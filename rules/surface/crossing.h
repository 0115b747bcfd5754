// The ray a path sends through a transmissive surface, or back from it into
// the solid, may meet the solid's far side closer than any fixed offset, or
// within the float's rounding of the vertex: glass thinner than the offset
// that clears the surface's own root (shadow_ray_offset). So that ray starts
// `back` before the vertex, along its own direction, with t from 0, and
// within twice that passes over every hit but the far side of the solid it
// travels in (docs/rendering.md, "Leaving a transmissive surface"): a hit
// of the same object that faces the ray as a surface it leaves, the normal
// oriented by the cage's winding. The surface at the vertex, met again
// about `back` along, faces the ray the other way and is passed over, as is
// a surface of another object touching it, which the offset cleared before.
// Found by its facing, not by its distance, the far side is kept however
// thin the solid.

#ifndef FACET_RULE_SURFACE_CROSSING
#define FACET_RULE_SURFACE_CROSSING

struct SurfaceCrossing {
  real back;    // along the ray; 0 for a ray that leaves no transmissive surface
  bool inside;  // the ray travels inside the solid: it enters there, direction . normal < 0
};

// Below this cosine between the ray and the surface `back` stops growing,
// so that a grazing ray does not pass over the rest of the scene.
const real CROSSING_MIN_COSINE = real(1) / real(32);

FACET_FN SurfaceCrossing no_crossing() {
  SurfaceCrossing c;
  c.back = real(0);
  c.inside = false;
  return c;
}

// The crossing of a ray along unit `direction` that leaves a surface of
// geometric normal ng (facing v, on the `outside` of the solid where v is):
// backed up so that it starts `offset` off the surface's plane.
FACET_FN SurfaceCrossing surface_crossing(vec3 direction, vec3 ng, bool outside, real offset) {
  real cosine = dot(direction, ng);
  SurfaceCrossing c;
  c.back = offset / max(abs(cosine), CROSSING_MIN_COSINE);
  c.inside = outside ? cosine < real(0) : cosine > real(0);
  return c;
}

FACET_FN vec3 crossing_origin(SurfaceCrossing c, vec3 vertex, vec3 direction) { return vertex - c.back * direction; }

// Whether the ray passes over a hit at `t` of geometric normal `normal`
// (any length, oriented by the winding), on the object it left or another.
FACET_FN bool crossing_passes_over(SurfaceCrossing c, bool same_object, real t, vec3 direction, vec3 normal) {
  if (!(t < real(2) * c.back)) return false;
  return !(c.inside && same_object && dot(direction, normal) > real(0));
}

#endif

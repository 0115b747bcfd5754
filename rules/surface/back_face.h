// glTF's one-sided surfaces (doubleSided false): a hit where the surface's
// geometric normal, oriented by the cage's winding, faces along the ray is a
// back face, and a culling object passes over it as if the surface were not
// there (docs/rendering.md, "One-sided surfaces"). A ray exactly in the
// surface's plane keeps the hit.

#ifndef FACET_RULE_SURFACE_BACK_FACE
#define FACET_RULE_SURFACE_BACK_FACE

FACET_FN bool is_back_face(vec3 direction, vec3 geometricNormal) {
  return dot(direction, geometricNormal) > real(0);
}

#endif

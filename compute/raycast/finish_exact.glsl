// The exact finish: the ray against the limit surface over one cell.
// Newton runs only where the ray passes through the cell's oriented bounds
// (compute/shared/wide_bvh.h), which exclude it from most cells whose box it
// merely crosses. Started from the cell's centre, it finds a root: a true
// intersection wherever on the patch it lies. A root inside the cell
// settles the cell; one beyond it settles the cell too when the ray is
// steeper to the cell's plane than the surface can be, so that it crosses
// the surface there at most once. Any other cell (Newton failed, or a
// grazing ray left it) goes to defer_cell(object, cell), which the including
// kernel defines: the fallback pass subdivides it (subdivide_cell.glsl).
// Kept out of the traversal because on lavapipe the subdivision's code
// slows the whole kernel even where it never runs. The including kernel
// declares patchHeaders, patchPoints and cellBounds. Needs ray.glsl,
// patch_eval.glsl, patch_hull.glsl.
#ifndef FACET_RAYCAST_FINISH_EXACT_GLSL
#define FACET_RAYCAST_FINISH_EXACT_GLSL

#include "compute/raycast/exact_newton.glsl"

OrientedBounds cell_bounds(uint cell) {
  int texel = int(cell * FACET_CELL_TEXELS);
  vec4 n = texelFetch(cellBounds, texel), u = texelFetch(cellBounds, texel + 1);
  vec4 ranges = texelFetch(cellBounds, texel + 2);
  return OrientedBounds(n.xyz, u.xyz, vec2(n.w, u.w), ranges.xy, ranges.zw, texelFetch(cellBounds, texel + 3).x);
}

void finish_exact(Ray ray, ObjectRange range, uint object, uint localPatch, uint i, uint j, inout Hit best) {
  bool steep;
  if (!ray_meets_bounds(ray, cell_bounds(range.firstCell + (localPatch * range.rate + j) * range.rate + i), best.t,
                        steep))
    return;
  uint patchIndex = range.firstPatch + localPatch;
  uvec4 header = texelFetch(patchHeaders, int(patchIndex));
  ControlPoints c = load_control_points(header[FACET_HEADER_FIRST_POINT], header[FACET_HEADER_KIND]);
  float size = 1.0 / float(range.rate);
  vec4 cell = vec4(float(i) * size, float(i + 1u) * size, float(j) * size, float(j + 1u) * size);
  if (!settled(newton(c, ray, patchIndex, object, cell, best), steep))
    defer_cell(object, (localPatch * range.rate + j) * range.rate + i);
}

#endif

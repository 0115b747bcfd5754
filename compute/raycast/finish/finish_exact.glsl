// The exact finish: the ray against the limit surface over one cell.
// Newton runs only where the ray passes through the cell's oriented bounds
// (compute/layout/wide_bvh.h), which exclude it from most cells whose box it
// merely crosses. Started where the ray crosses the cell's plane, it finds
// a root: a true intersection wherever on the patch it lies. A root inside
// the cell settles the cell; one beyond it settles the cell too when the ray is
// steeper to the cell's plane than the surface can be, so that it crosses
// the surface there at most once. Any other cell (Newton failed, or a
// grazing ray left it) goes to defer_cell(reference), which the including
// kernel defines: the fallback pass subdivides it (subdivide_cell.glsl).
// Kept out of the traversal because on lavapipe the subdivision's code
// slows the whole kernel even where it never runs. The including kernel
// declares patchPoints and cellBounds. Needs ray.glsl, patch_eval.glsl,
// patch_hull.glsl, micro_grid.glsl.
#ifndef FACET_RAYCAST_FINISH_EXACT_GLSL
#define FACET_RAYCAST_FINISH_EXACT_GLSL

#include "compute/raycast/finish/exact_newton.glsl"

OrientedBounds cell_bounds(uint cell) {
  int texel = int(cell * FACET_CELL_TEXELS);
  vec4 n = texelFetch(cellBounds, texel), u = texelFetch(cellBounds, texel + 1);
  vec4 ranges = texelFetch(cellBounds, texel + 2);
  return OrientedBounds(n.xyz, u.xyz, vec2(n.w, u.w), ranges.xy, ranges.zw, texelFetch(cellBounds, texel + 3).x);
}

void finish_exact(Ray ray, Cell cell, uint reference, inout Hit best) {
  bool steep;
  vec2 across, entry;
  if (!ray_meets_bounds(ray, cell_bounds(cell.firstCell + cell.j * cell.rate + cell.i), best.t, steep, across, entry))
    return;
  ControlPoints c = load_control_points(cell.firstPoint, cell.kind);
  vec4 domain = cell_domain(cell);
  // A grazing ray may cross a curved cell twice and Newton find the farther
  // crossing: a second run, from where the ray enters the cell's bounds,
  // looks for a nearer one, which replaces the hit. One call site in a loop:
  // on lavapipe a second inlined Newton slows the whole traversal.
  int result = NEWTON_FAILED;
  for (int run = 0; run < 2; ++run) {
    int found = newton(c, ray, cell.patchIndex, cell.object, domain, run == 0 ? across : entry, best);
    if (run == 0) result = found;
    if (steep || result != NEWTON_ROOT_INSIDE) break;
  }
  if (!settled(result, steep)) defer_cell(reference);
}

#endif

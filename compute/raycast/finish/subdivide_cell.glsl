// The exact method's fallback: the ray against the limit surface over one
// cell by subdivision of its domain, pieces culled by their oriented
// bounds and decided by Newton as the cells are (finish_exact.glsl), down to
// pieces too small to split (the CPU reference's method,
// engine/cpu/intersect.h). Needs exact_newton.glsl and patch_hull.glsl.
#ifndef FACET_RAYCAST_SUBDIVIDE_CELL_GLSL
#define FACET_RAYCAST_SUBDIVIDE_CELL_GLSL

const uint SUBDIVISION_MAX_DEPTH = 16u;

// Pieces of `cell` as (depth, i, j): cell + [i, i + 1] x [j, j + 1] / 2^depth,
// walked depth first without a stack (lavapipe makes a private array indexed
// at run time slow): after a piece, the next sibling in the order (0,0),
// (1,0), (0,1), (1,1), climbing past last children. Each halving halves a
// smooth piece's steepness, so only rays close to tangent go deep.
void subdivide_cell(ControlPoints c, Ray ray, uint patchIndex, uint object, vec4 cell, inout Hit best) {
  vec2 cellSize = vec2(cell.y - cell.x, cell.w - cell.z);
  uint depth = 0u, i = 0u, j = 0u;
  while (true) {
    vec2 size = cellSize / float(1u << depth);
    vec4 domain = vec4(cell.x + float(i) * size.x, cell.x + float(i + 1u) * size.x, cell.z + float(j) * size.y,
                       cell.z + float(j + 1u) * size.y);
    OrientedBounds bounds =
        oriented_bounds(restrict_patch(c, domain.x, domain.y, domain.z, domain.w), 2.0 * frame.tolerance);
    bool steep, split = false;
    vec2 across, entry;
    if (ray_meets_bounds(ray, bounds, best.t, steep, across, entry)) {
      bool splittable = depth < SUBDIVISION_MAX_DEPTH && extent(bounds) > frame.minimumPiece;
      split = splittable && !(steep && settled(newton(c, ray, patchIndex, object, domain, across, best), steep));
      if (!splittable) newton(c, ray, patchIndex, object, domain, across, best);
    }
    if (split) {
      ++depth;
      i *= 2u;
      j *= 2u;
      continue;
    }
    while (depth > 0u && (i & 1u) == 1u && (j & 1u) == 1u) {
      --depth;
      i >>= 1u;
      j >>= 1u;
    }
    if (depth == 0u) return;
    if ((i & 1u) == 0u) {
      ++i;
    } else {
      --i;
      ++j;
    }
  }
}

#endif

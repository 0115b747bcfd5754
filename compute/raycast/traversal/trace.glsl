// The one intersection interface of the GPU ray caster: trace(ray, anyHit)
// returns the closest hit through the scene's 4-wide BVH over the objects'
// micro-grids, or with anyHit the first hit found. METHOD (a specialization
// constant of the including kernel: 0 exact, 1 tessellated) picks what
// happens at a cell. The including kernel declares the bindings of
// trace_bindings.glsl and defines defer_cell(object, cell), where the exact
// method sends the cells Newton leaves undecided (finish_exact.glsl).
#ifndef FACET_RAYCAST_TRACE_GLSL
#define FACET_RAYCAST_TRACE_GLSL

#include "compute/raycast/common/ray.glsl"
#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/common/patch_hull.glsl"
#include "compute/raycast/common/micro_grid.glsl"
#include "compute/raycast/common/cell_reference.glsl"
#include "compute/raycast/finish/triangle.glsl"
#include "compute/raycast/finish/finish_exact.glsl"
#include "compute/raycast/finish/finish_tessellated.glsl"

const int METHOD_EXACT = 0;
const int METHOD_TESSELLATED = 1;

void finish_cell(Ray ray, uint reference, inout Hit best) {
  Cell cell = cell_of(reference);
  if (METHOD == METHOD_EXACT)
    finish_exact(ray, cell, reference, best);
  else
    finish_tessellated(ray, cell, best);
}

#include "compute/raycast/traversal/wide_bvh_traversal.glsl"

Hit trace(Ray ray, bool anyHit) {
  Hit best = no_hit(ray.tMax);
  traverse(ray, anyHit, best);
  return best;
}

#endif

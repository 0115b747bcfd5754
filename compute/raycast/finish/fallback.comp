// The exact cells that Newton left undecided (finish_exact.glsl), one
// invocation each, subdivided (subdivide_cell.glsl). Camera rays
// (SHADOW = 0): a root nearer than the ray's hit so far lowers the hit's t
// (atomically: a ray may have several such cells) and is kept in the record
// for fallback_resolve.comp. Shadow rays (SHADOW = 1): any root blocks the
// light, clearing the ray's slot. PATHS = 1 (with SHADOW = 0): the cells of
// continuation rays, whose ray is the compacted list's (docs/rendering.md,
// "Paths") and whose hit is at its index in that list.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/common/trace_bindings.glsl"

layout(constant_id = 0) const int SHADOW = 0;
layout(constant_id = 1) const int PATHS = 0;

// The camera hits as words: a HitRecord's t first, its float bits ordered as
// the floats (t >= 0), so atomicMin keeps the nearest.
layout(set = 0, binding = 9, std430) buffer HitWords { uint hitWords[]; };
layout(set = 0, binding = 14, std430) readonly buffer ShadowRays { ShadowRayRecord shadowRays[]; };
layout(set = 0, binding = 15, std430) buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 24, std430) buffer CameraFallbacks { FallbackRecord cameraFallbacks[]; };
layout(set = 0, binding = 25, std430) readonly buffer ShadowFallbacks { FallbackRecord shadowFallbacks[]; };
layout(set = 0, binding = 33, std430) readonly buffer PathRays { PathRayRecord pathRays[]; };

#include "compute/raycast/common/ray.glsl"
#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/common/patch_hull.glsl"
#include "compute/raycast/finish/exact_newton.glsl"
#include "compute/raycast/finish/subdivide_cell.glsl"
#include "compute/raycast/common/micro_grid.glsl"
#include "compute/raycast/common/cell_reference.glsl"
#include "compute/raycast/common/camera_rays.glsl"

const uint HIT_WORDS = 8u;  // sizeof(HitRecord) / 4

void main() {
  uint index = invocation_index();
  uint count = min(SHADOW == 1 ? counters.shadowFallbacks : counters.cameraFallbacks, frame.fallbackCapacity);
  if (index >= count) return;
  FallbackRecord record;
  Ray ray;
  if (SHADOW == 1) {
    record = shadowFallbacks[index];
    ray = to_ray(shadowRays[record.ray].ray);
    if (CUTOUTS == 2) passThroughKey = shadow_ray_key(shadowRays[record.ray].slot);
  } else {
    record = cameraFallbacks[index];
    ray = PATHS == 1 ? to_ray(pathRays[record.ray].ray) : camera_ray(record.ray);
    ray.tMax = uintBitsToFloat(hitWords[HIT_WORDS * record.ray]);
    if (CUTOUTS == 2) passThroughKey = nearest_ray_key(PATHS == 1 ? pathRays[record.ray].path : record.ray);
    if (CROSSINGS == 1) set_crossing(pathRays[record.ray]);
  }
  Cell cell = cell_of(record.cell);
  Hit best = no_hit(ray.tMax);
  subdivide_cell(load_control_points(cell.firstPoint, cell.kind), ray, cell.patchIndex, cell.object, cell_domain(cell),
                 best);
  if (best.patchIndex == FACET_NO_HIT) return;
  if (SHADOW == 1) {
    contributions[shadowRays[record.ray].slot] = vec4(0.0);
    return;
  }
  cameraFallbacks[index].object = best.object;
  cameraFallbacks[index].t = best.t;
  cameraFallbacks[index].patchIndex = best.patchIndex;
  cameraFallbacks[index].s = best.st.x;
  cameraFallbacks[index].tParam = best.st.y;
  atomicMin(hitWords[HIT_WORDS * record.ray], floatBitsToUint(best.t));
}

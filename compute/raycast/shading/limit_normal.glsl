// The limit normal with the fallback both backends share
// (rules/surface/limit_normal.h), over this kernel's patch evaluation.
// Needs patch_eval.glsl.
#ifndef FACET_RAYCAST_LIMIT_NORMAL_GLSL
#define FACET_RAYCAST_LIMIT_NORMAL_GLSL

#include "rules/language.glsl"
#include "rules/surface/limit_normal.h"

vec3 limit_normal(ControlPoints c, float s, float t) {
  vec3 normal;
  PatchSample point = evaluate_patch(c, s, t);
  if (well_defined_normal(point.ds, point.dt, normal)) return normal;
  for (int probe = 0; probe < LIMIT_NORMAL_PROBES; ++probe) {
    float step = limit_normal_probe_step(probe);
    point = evaluate_patch(c, toward_patch_centre(s, 0.5, step), toward_patch_centre(t, 0.5, step));
    if (well_defined_normal(point.ds, point.dt, normal)) return normal;
  }
  PatchSample centre = evaluate_patch(c, 0.5, 0.5);
  return unit_normal_or_up(cross(centre.ds, centre.dt));
}

#endif

// The limit normal dP/ds x dP/dt with the CPU reference's fallback
// (engine/cpu/limit_normal.h): where the cross product vanishes, step
// towards the patch centre by growing fractions. Needs patch_eval.glsl.
#ifndef FACET_RAYCAST_LIMIT_NORMAL_GLSL
#define FACET_RAYCAST_LIMIT_NORMAL_GLSL

const float DEGENERATE_SINE = 1e-6;

bool well_defined_normal(PatchSample point, out vec3 normal) {
  vec3 n = cross(point.ds, point.dt);
  float scale = length(point.ds) * length(point.dt);
  normal = vec3(0.0);
  if (!(scale > 0.0) || length(n) <= DEGENERATE_SINE * scale) return false;
  normal = normalize(n);
  return true;
}

vec3 limit_normal(ControlPoints c, float s, float t) {
  vec3 normal;
  if (well_defined_normal(evaluate_patch(c, s, t), normal)) return normal;
  for (float step = 1e-7; step <= 1.5e-3; step *= 10.0)
    if (well_defined_normal(evaluate_patch(c, s + step * (0.5 - s), t + step * (0.5 - t)), normal)) return normal;
  PatchSample centre = evaluate_patch(c, 0.5, 0.5);
  vec3 fallback = cross(centre.ds, centre.dt);
  float len = length(fallback);
  return len > 0.0 ? fallback / len : vec3(0.0, 0.0, 1.0);
}

#endif

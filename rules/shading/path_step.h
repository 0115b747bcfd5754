// One step of a path from a shaded vertex to the ray that leaves it, in the
// one order both backends take it (docs/rendering.md, "Paths"): Russian
// roulette, the continuation (opaque or through a transmissive interface),
// the limit of its lobe kind, the end of a path that carries nothing, and the
// medium the new ray travels in. A backend fetches the vertex and its path's
// state and stores what this rule returns.

#ifndef FACET_RULE_SHADING_PATH_STEP
#define FACET_RULE_SHADING_PATH_STEP

#include "rules/sampling/path_samples.h"
#include "rules/shading/brdf.h"
#include "rules/shading/lights.h"
#include "rules/shading/path_continuation.h"
#include "rules/shading/transmissive_continuation.h"
#include "rules/surface/crossing.h"

// Which random numbers a path draws (rules/sampling/path_samples.h): the
// pixel of the full image, the camera sample of `samples`, the scene's seed.
struct PathSampleKey {
  uint pixel;
  uint sample_index;
  uint samples;
  uint seed;
};

// A shaded vertex a path continues from: its normals face v.
struct PathVertex {
  vec3 position;
  vec3 n;
  vec3 ng;
  vec3 v;
  BrdfParams params;
  vec3 specular_scale;
  bool transmissive;  // continues by continue_path_transmissive, with `transmission`
  TransmissionParams transmission;
  bool outside;  // v on the side the outward geometric normal points to
};

// What a path carries from one vertex to the next.
struct PathCarry {
  vec3 throughput;
  vec3 sigma;   // absorption of the medium it travels in: air, or inside a transmissive object
  uvec3 taken;  // continuations of each lobe kind (PATH_LOBE_*) so far
};

// What a camera ray's path carries to its first vertex: it starts in the
// medium around the eye (scene::cameraMedium; sigma 0 in air), whose
// absorption over the camera ray's segment scales all the vertex and the
// path after it bring to the eye (docs/rendering.md, "The camera inside a
// medium").
FACET_FN PathCarry camera_path_start(vec3 eye_sigma, vec3 eye, vec3 first_vertex) {
  PathCarry carry;
  carry.throughput = segment_transmittance(eye_sigma, eye, first_vertex);
  carry.sigma = eye_sigma;
  carry.taken = uvec3(uint(0));
  return carry;
}

struct PathStep {
  bool continues;  // false: roulette ended it, its lobe kind is over its limit, or it carries nothing
  PathCarry carry;
  vec3 origin;  // of the ray that leaves the vertex
  vec3 direction;
  real t_min;                // of that ray
  SurfaceCrossing crossing;  // where it leaves a transmissive surface (rules/surface/crossing.h)
  bool transmitted;
};

// The step from vertex number `vertex` (1 for the camera ray's hit).
// `limited`: whether any lobe kind has a limit (`limits`, -1 for none); where
// none has, the lobe kinds are neither told apart nor counted.
FACET_FN PathStep path_step(PathVertex x, PathCarry carry, PathSampleKey key, uint vertex, bool limited,
                            ivec3 limits, real offset) {
  PathStep step;
  step.continues = false;
  step.carry = carry;
  step.origin = x.position;
  step.direction = vec3(real(0));
  step.t_min = offset;
  step.crossing = no_crossing();
  step.transmitted = false;
  real survival = path_survival_probability(carry.throughput, vertex);
  if (survival < real(1)) {
    if (path_roulette_u(key.pixel, key.sample_index, key.samples, key.seed, vertex) >= survival) return step;
    step.carry.throughput = step.carry.throughput / survival;
  }
  vec2 u = path_continuation_u(key.pixel, key.sample_index, key.samples, key.seed, vertex);
  int lobe = PATH_LOBE_DIFFUSE;
  vec3 weight;
  if (x.transmissive) {
    TransmissiveContinuation next =
        continue_path_transmissive(x.params, x.transmission, x.n, x.ng, x.v, x.specular_scale, u,
                                   path_interface_u(key.pixel, key.sample_index, key.samples, key.seed, vertex));
    step.direction = next.direction;
    step.transmitted = next.transmitted;
    lobe = next.lobe;
    weight = next.weight;
    // Through the interface of a solid (not a thin wall): into its medium from outside, back into air from inside.
    if (step.transmitted && !x.transmission.thin_walled)
      step.carry.sigma = x.outside ? x.transmission.sigma : vec3(real(0));
  } else {
    PathContinuation next = continue_path(x.params, x.n, x.ng, x.v, x.specular_scale, u);
    step.direction = next.direction;
    weight = next.weight;
    if (limited) lobe = opaque_continuation_lobe(x.params, x.n, x.v, u);
  }
  step.carry.throughput = step.carry.throughput * weight;
  if (limited) {
    if (!path_lobe_allowed(int(step.carry.taken[lobe]), limits[lobe])) return step;
    step.carry.taken[lobe] += uint(1);
  }
  if (step.carry.throughput == vec3(real(0))) return step;
  step.continues = true;
  if (x.transmissive) {
    // Through the surface or off it, the solid's far side may be nearer than the offset.
    step.t_min = real(0);
    step.crossing = surface_crossing(step.direction, x.ng, x.outside, offset);
    step.origin = crossing_origin(step.crossing, x.position, step.direction);
  } else {
    step.origin = shadow_ray_origin(x.position, x.ng, offset);
  }
  return step;
}

#endif

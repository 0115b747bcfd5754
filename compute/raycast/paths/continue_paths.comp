// Paths (docs/rendering.md, "Paths"), one invocation per camera ray of the
// band: a live path's Russian roulette (from PATH_FIRST_ROULETTE_BOUNCE on)
// and its continuation from vertex frame.pathVertex by the shared rule
// continue_path, with the numbers of rules/sampling/path_samples.h keyed as
// the CPU reference keys them (the pixel of the full image, the camera
// sample, the scene's seed), so that both backends trace the same paths. A
// path that goes on multiplies its throughput by the continuation's weight
// and appends its ray to the compacted list (counters.pathRays); one that
// ends is marked so.
// TRANSMISSION (docs/rendering.md, "Transmission and absorption"): 1 when
// some material transmits; a vertex of one continues by
// continue_path_transmissive with path_interface_u, its ray leaves below the
// surface where it goes through, and a path that enters a medium (not a thin
// wall) takes its sigma, one that leaves it sigma 0, as the CPU reference's
// tracePath does.
// LOBE_LIMITS (docs/rendering.md, "Limits per lobe kind"): 1 when the scene
// sets a limit; the path counts its continuations per lobe kind and ends at
// one that path_lobe_allowed refuses, checked where tracePath checks it
// (after roulette and the continuation, before the zero throughput).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/raycast_layout.h"
#include "compute/raycast/common/workgroup.glsl"
#include "compute/raycast/common/ray.glsl"
#include "rules/language.glsl"
#include "rules/sampling/path_samples.h"
#include "rules/shading/lights.h"
#include "rules/shading/path_continuation.h"
#include "rules/shading/transmissive_continuation.h"

layout(constant_id = 0) const int TRANSMISSION = 0;
layout(constant_id = 1) const int LOBE_LIMITS = 0;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 11, std430) readonly buffer Materials { MaterialRecord materials[]; };
layout(set = 0, binding = 32, std430) buffer PathStates { PathState pathStates[]; };
layout(set = 0, binding = 33, std430) writeonly buffer PathRays { PathRayRecord pathRays[]; };

#include "compute/raycast/common/path_state.glsl"

void main() {
  uint path = invocation_index();
  if (path >= frame.pixelCount * frame.raysPerPixel) return;
  if (pathStates[path].alive == 0u) return;  // before loading the rest: most paths end early
  PathState state = pathStates[path];
  uint pixel = frame.firstPixel + path / frame.raysPerPixel, sample_index = path % frame.raysPerPixel;
  uint vertex = frame.pathVertex;
  vec3 throughput = path_throughput(state);
  float survival = path_survival_probability(throughput, vertex);
  if (survival < 1.0) {
    if (path_roulette_u(pixel, sample_index, frame.raysPerPixel, frame.pathSeed, vertex) >= survival) {
      pathStates[path].alive = 0u;
      return;
    }
    throughput /= survival;
  }
  vec2 u = path_continuation_u(pixel, sample_index, frame.raysPerPixel, frame.pathSeed, vertex);
  PathVertex x = path_vertex(state);
  PathMedium medium = path_medium(state);
  vec3 direction, weight;
  bool transmitted = false;
  int lobe = PATH_LOBE_DIFFUSE;
  if (TRANSMISSION == 1 && (medium.flags & FACET_PATH_TRANSMISSIVE) != 0u) {
    TransmissionParams t = transmission_params(materials[medium.material]);
    TransmissiveContinuation next =
        continue_path_transmissive(x.params, t, x.n, x.ng, x.v, u,
                                   path_interface_u(pixel, sample_index, frame.raysPerPixel, frame.pathSeed, vertex));
    direction = next.direction;
    weight = next.weight;
    transmitted = next.transmitted;
    lobe = next.lobe;
    if (transmitted && !t.thin_walled)
      medium.sigma = (medium.flags & FACET_PATH_OUTSIDE) != 0u ? t.sigma : vec3(0.0);
  } else {
    PathContinuation next = continue_path(x.params, x.n, x.ng, x.v, x.specular_scale, u);
    direction = next.direction;
    weight = next.weight;
    if (LOBE_LIMITS == 1) lobe = opaque_continuation_lobe(x.params, x.n, x.v, u);
  }
  throughput *= weight;
  if (LOBE_LIMITS == 1) {
    uvec3 taken = path_lobes_taken(state);
    ivec3 limits = ivec3(frame.diffuseBounces, frame.glossyBounces, frame.transmissionBounces);
    if (!path_lobe_allowed(int(taken[lobe]), limits[lobe])) {
      pathStates[path].alive = 0u;
      return;
    }
    taken[lobe] += 1u;
    pathStates[path].diffuseTaken = taken.x;
    pathStates[path].glossyTaken = taken.y;
    pathStates[path].transmissionTaken = taken.z;
  }
  if (throughput == vec3(0.0)) {
    pathStates[path].alive = 0u;
    return;
  }
  pathStates[path].throughputR = throughput.x;
  pathStates[path].throughputG = throughput.y;
  pathStates[path].throughputB = throughput.z;
  if (TRANSMISSION == 1) {
    pathStates[path].flags = transmitted ? medium.flags | FACET_PATH_TRANSMITTED : medium.flags;
    pathStates[path].sigmaR = medium.sigma.x;
    pathStates[path].sigmaG = medium.sigma.y;
    pathStates[path].sigmaB = medium.sigma.z;
  }
  vec3 origin = shadow_ray_origin(x.position, transmitted ? -x.ng : x.ng, frame.shadowOffset);
  pathRays[atomicAdd(counters.pathRays, 1u)] = PathRayRecord(
      RayRecord(origin.x, origin.y, origin.z, frame.shadowOffset, direction.x, direction.y, direction.z,
                INFINITE_DISTANCE),
      path);
}

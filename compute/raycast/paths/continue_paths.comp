// Paths (docs/rendering.md, "Paths"), one invocation per camera ray of the
// band: a live path's Russian roulette (from PATH_FIRST_ROULETTE_BOUNCE on)
// and its continuation from vertex frame.pathVertex by the shared rule
// continue_path, with the numbers of rules/sampling/path_samples.h keyed as
// the CPU reference keys them (the pixel of the full image, the camera
// sample, the scene's seed), so that both backends trace the same paths. A
// path that goes on multiplies its throughput by the continuation's weight
// and appends its ray to the compacted list (counters.pathRays); one that
// ends is marked so.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/raycast_layout.h"
#include "compute/raycast/common/workgroup.glsl"
#include "compute/raycast/traversal/ray.glsl"
#include "rules/language.glsl"
#include "rules/math.h"
#include "rules/shading/domain.h"
#include "rules/shading/microfacet.h"
#include "rules/shading/fresnel.h"
#include "rules/shading/brdf.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/lights.h"
#include "rules/sampling/random.h"
#include "rules/sampling/low_discrepancy.h"
#include "rules/sampling/scrambled_net.h"
#include "rules/sampling/path_samples.h"
#include "rules/shading/lobe_sampling.h"
#include "rules/shading/path_continuation.h"

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 32, std430) buffer PathStates { PathState pathStates[]; };
layout(set = 0, binding = 33, std430) writeonly buffer PathRays { PathRayRecord pathRays[]; };

#include "compute/raycast/paths/path_state.glsl"

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
  PathContinuation next = continue_path(x.params, x.n, x.ng, x.v, x.specular_scale, u);
  throughput *= next.weight;
  if (throughput == vec3(0.0)) {
    pathStates[path].alive = 0u;
    return;
  }
  pathStates[path].throughputR = throughput.x;
  pathStates[path].throughputG = throughput.y;
  pathStates[path].throughputB = throughput.z;
  vec3 origin = shadow_ray_origin(x.position, x.ng, frame.shadowOffset);
  pathRays[atomicAdd(counters.pathRays, 1u)] =
      PathRayRecord(RayRecord(origin.x, origin.y, origin.z, frame.shadowOffset, next.direction.x, next.direction.y,
                              next.direction.z, INFINITE_DISTANCE),
                    path);
}

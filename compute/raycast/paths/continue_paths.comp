// Paths (docs/rendering.md, "Paths"), one invocation per path of the live
// list that the last bounce's surface kernel made: its step from vertex
// frame.pathVertex by the shared rule path_step (rules/shading/path_step.h),
// keyed as the CPU reference keys it, so that both backends trace the same
// paths. A path that goes on stores what it carries and appends its ray to
// the compacted list (counters.pathRays); one that ends appends nothing.
// TRANSMISSION: 1 when some material transmits (a vertex may then be
// transmissive, and a path carries its medium). LOBE_LIMITS: 1 when the
// scene limits some lobe kind (a path then counts its lobes).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/raycast_layout.h"
#include "compute/layout/path_layout.h"
#include "compute/raycast/common/workgroup.glsl"
#include "compute/raycast/common/ray.glsl"
#include "rules/language.glsl"
#include "rules/shading/path_step.h"

layout(constant_id = 0) const int TRANSMISSION = 0;
layout(constant_id = 1) const int LOBE_LIMITS = 0;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 11, std430) readonly buffer Materials { MaterialRecord materials[]; };
layout(set = 0, binding = 32, std430) buffer PathStates { PathState pathStates[]; };
layout(set = 0, binding = 33, std430) writeonly buffer PathRays { PathRayRecord pathRays[]; };
layout(set = 0, binding = 34, std430) readonly buffer LivePaths { uint livePaths[]; };

#include "compute/raycast/common/path_state.glsl"
#include "compute/raycast/common/band_pixels.glsl"

void main() {
  uint index = invocation_index();
  if (index >= counters.livePaths) return;
  uint path = livePaths[index];
  PathState state = pathStates[path];
  PathMedium medium = path_medium(state);
  bool transmissive = TRANSMISSION == 1 && (medium.flags & FACET_PATH_TRANSMISSIVE) != 0u;
  TransmissionParams transmission;
  if (transmissive) {
    transmission = transmission_params(materials[medium.material]);
    transmission.transmission = medium.transmission;
  }
  PathSampleKey key =
      PathSampleKey(image_pixel(path / frame.raysPerPixel), path % frame.raysPerPixel, frame.raysPerPixel, frame.pathSeed);
  PathCarry carry = PathCarry(path_throughput(state), medium.sigma, path_lobes_taken(state));
  PathStep step = path_step(path_vertex(state, transmissive, transmission), carry, key, frame.pathVertex,
                            LOBE_LIMITS == 1, ivec3(frame.diffuseBounces, frame.glossyBounces, frame.transmissionBounces),
                            frame.shadowOffset);
  if (!step.continues) return;
  pathStates[path].throughputR = step.carry.throughput.x;
  pathStates[path].throughputG = step.carry.throughput.y;
  pathStates[path].throughputB = step.carry.throughput.z;
  if (LOBE_LIMITS == 1) {
    pathStates[path].diffuseTaken = step.carry.taken.x;
    pathStates[path].glossyTaken = step.carry.taken.y;
    pathStates[path].transmissionTaken = step.carry.taken.z;
  }
  if (TRANSMISSION == 1) {
    pathStates[path].flags = step.transmitted ? medium.flags | FACET_PATH_TRANSMITTED : medium.flags;
    pathStates[path].sigmaR = step.carry.sigma.x;
    pathStates[path].sigmaG = step.carry.sigma.y;
    pathStates[path].sigmaB = step.carry.sigma.z;
  }
  pathRays[atomicAdd(counters.pathRays, 1u)] =
      PathRayRecord(RayRecord(step.origin.x, step.origin.y, step.origin.z, step.t_min, step.direction.x,
                              step.direction.y, step.direction.z, INFINITE_DISTANCE),
                    path, medium.object, step.crossing.back, step.crossing.inside ? 1u : 0u);
}

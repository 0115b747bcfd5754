// Per camera ray, the radiance of its slot contributions (lights,
// environment, or what a miss sees; the shadow pass cleared those it found
// blocked), and whether it hit (in w). A pass of its own so that
// no invocation loops over a pixel's samples times their slots: lavapipe
// ends an invocation's loops after 65535 iterations in all.
// PATHS = 1 (docs/rendering.md, "Paths"): per continuation ray of the
// compacted list that hit (dispatched indirectly), D at the vertex it hit,
// in its path's slots, times the path's throughput, added to the camera
// ray's radiance. TRANSMISSION = 1 (docs/rendering.md, "Transmission and
// absorption"): a continuation ray that went through its last surface and
// missed adds what the surface kernel wrote in its slots, the environment.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/raycast_layout.h"
#include "compute/layout/path_layout.h"
#include "compute/raycast/common/workgroup.glsl"

layout(constant_id = 0) const int PATHS = 0;
layout(constant_id = 1) const int TRANSMISSION = 0;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 9, std430) readonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 15, std430) readonly buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 22, std430) buffer RayRadiance { vec4 rayRadiance[]; };
layout(set = 0, binding = 10, std430) readonly buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 32, std430) readonly buffer PathStates { PathState pathStates[]; };
layout(set = 0, binding = 33, std430) readonly buffer PathRays { PathRayRecord pathRays[]; };

vec3 slot_radiance(uint ray) {
  vec3 radiance = vec3(0.0);
  for (uint slot = ray * frame.slotsPerRay; slot < (ray + 1u) * frame.slotsPerRay; ++slot)
    radiance += contributions[slot].xyz;
  return radiance;
}

void main() {
  uint index = invocation_index();
  if (PATHS == 1) {
    if (index >= counters.pathRays) return;
    uint path = pathRays[index].path;
    if (hits[index].patchIndex == FACET_NO_HIT &&
        (TRANSMISSION == 0 || (pathStates[path].flags & FACET_PATH_TRANSMITTED) == 0u))
      return;
    PathState state = pathStates[path];
    vec3 throughput = vec3(state.throughputR, state.throughputG, state.throughputB);
    rayRadiance[path].xyz += throughput * slot_radiance(path);
    return;
  }
  if (index >= frame.pixelCount * frame.raysPerPixel) return;
  rayRadiance[index] = vec4(slot_radiance(index), hits[index].patchIndex == FACET_NO_HIT ? 0.0 : 1.0);
}

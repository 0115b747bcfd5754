// The compacted shadow rays (counters.shadowRays of them, dispatched
// indirectly): any hit before the light blocks it, and the light's
// contribution in the ray's slot is cleared. Exact cells Newton leaves
// undecided are listed for the fallback pass, unless a hit is found first.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/common/trace_bindings.glsl"

layout(constant_id = 0) const int METHOD = 0;

layout(set = 0, binding = 14, std430) readonly buffer ShadowRays { ShadowRayRecord shadowRays[]; };
layout(set = 0, binding = 15, std430) buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 25, std430) writeonly buffer ShadowFallbacks { FallbackRecord shadowFallbacks[]; };

uint rayIndex;

void defer_cell(uint reference) {
  uint at = atomicAdd(counters.shadowFallbacks, 1u);
  if (at < frame.fallbackCapacity) shadowFallbacks[at] = FallbackRecord(rayIndex, reference, 0u, 0.0, FACET_NO_HIT, 0.0, 0.0);
}

#include "compute/raycast/traversal/trace.glsl"

void main() {
  uint index = invocation_index();
  if (index >= counters.shadowRays) return;
  rayIndex = index;
  ShadowRayRecord record = shadowRays[index];
  if (CUTOUTS == 2) passThroughKey = shadow_ray_key(record.slot);
  if (trace(to_ray(record.ray), true).patchIndex != FACET_NO_HIT) contributions[record.slot] = vec4(0.0);
}

// Camera rays' fallback cells, one invocation each: the cell whose root is
// the ray's nearest hit (the t that fallback.comp's atomicMin left) writes
// the rest of the hit. The exact method's geometric normal is found when
// shading, so it stays 0.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"

layout(set = 0, binding = 10, std430) readonly buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 9, std430) buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 24, std430) readonly buffer CameraFallbacks { FallbackRecord cameraFallbacks[]; };

void main() {
  uint index = invocation_index();
  if (index >= min(counters.cameraFallbacks, frame.fallbackCapacity)) return;
  FallbackRecord record = cameraFallbacks[index];
  if (record.patchIndex == FACET_NO_HIT || floatBitsToUint(record.t) != floatBitsToUint(hits[record.ray].t)) return;
  hits[record.ray] = HitRecord(record.t, record.patchIndex, record.object, record.s, record.tParam, 0.0, 0.0, 0.0);
}

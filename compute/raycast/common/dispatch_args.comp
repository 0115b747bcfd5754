// One invocation: the workgroup grids of the passes that work off the
// kernels' lists (compute/layout/raycast_layout.h's RenderCounters), from
// their lengths so far, as invocation_index() (workgroup.glsl) expects them.
// Run after each pass that appends.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/grid/workgroup_grid.h"
#include "compute/layout/raycast_layout.h"

layout(local_size_x = 1) in;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };

void main() {
  uvec3 shadow = workgroup_grid(counters.shadowRays);
  // A list that overflowed is worked off as far as it holds; the host sees
  // the count and renders the band again with room for all.
  uvec3 camera = workgroup_grid(min(counters.cameraFallbacks, frame.fallbackCapacity));
  uvec3 shadowFallback = workgroup_grid(min(counters.shadowFallbacks, frame.fallbackCapacity));
  counters.shadowX = shadow.x;
  counters.shadowY = shadow.y;
  counters.shadowZ = shadow.z;
  counters.cameraFallbackX = camera.x;
  counters.cameraFallbackY = camera.y;
  counters.cameraFallbackZ = camera.z;
  counters.shadowFallbackX = shadowFallback.x;
  counters.shadowFallbackY = shadowFallback.y;
  counters.shadowFallbackZ = shadowFallback.z;
  uvec3 path = workgroup_grid(counters.pathRays);  // paths' continuation rays (0 without paths)
  counters.pathX = path.x;
  counters.pathY = path.y;
  counters.pathZ = path.z;
  uvec3 live = workgroup_grid(counters.livePaths);  // paths that go on (0 without paths)
  counters.liveX = live.x;
  counters.liveY = live.y;
  counters.liveZ = live.z;
}

// The closest hit of each camera ray, by the method METHOD (0 exact,
// 1 tessellated); exact cells Newton leaves undecided are listed for the
// fallback pass. PATHS = 1: of each continuation ray of the compacted list
// instead (counters.pathRays of them, dispatched indirectly; docs/rendering.md,
// "Paths"), its hit at its index in the list.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/common/trace_bindings.glsl"

layout(constant_id = 0) const int METHOD = 0;
layout(constant_id = 1) const int PATHS = 0;

layout(set = 0, binding = 9, std430) writeonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 24, std430) writeonly buffer CameraFallbacks { FallbackRecord cameraFallbacks[]; };
layout(set = 0, binding = 33, std430) readonly buffer PathRays { PathRayRecord pathRays[]; };

uint rayIndex;

void defer_cell(uint reference) {
  uint at = atomicAdd(counters.cameraFallbacks, 1u);
  if (at < frame.fallbackCapacity) cameraFallbacks[at] = FallbackRecord(rayIndex, reference, 0u, 0.0, FACET_NO_HIT, 0.0, 0.0);
}

#include "compute/raycast/traversal/trace.glsl"
#include "compute/raycast/common/camera_rays.glsl"

void main() {
  uint index = invocation_index();
  if (index >= (PATHS == 1 ? counters.pathRays : frame.pixelCount * frame.raysPerPixel)) return;
  rayIndex = index;
  if (CUTOUTS == 2) passThroughKey = nearest_ray_key(PATHS == 1 ? pathRays[index].path : index);
  if (CROSSINGS == 1) set_crossing(pathRays[index]);
  Hit hit = trace(PATHS == 1 ? to_ray(pathRays[index].ray) : camera_ray(index), false);
  hits[index] = HitRecord(hit.t, hit.patchIndex, hit.object, hit.st.x, hit.st.y, hit.geometricNormal.x,
                          hit.geometricNormal.y, hit.geometricNormal.z);
}

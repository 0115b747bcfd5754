// The closest hit of each camera ray, by the method METHOD (0 exact,
// 1 tessellated).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/scene_bindings.glsl"
#include "compute/raycast/trace_bindings.glsl"

layout(constant_id = 0) const int METHOD = 0;

layout(set = 0, binding = 8, std430) readonly buffer Rays { RayRecord rays[]; };
layout(set = 0, binding = 9, std430) writeonly buffer Hits { HitRecord hits[]; };

#include "compute/raycast/trace.glsl"

void main() {
  uint index = invocation_index();
  if (index >= frame.pixelCount * frame.raysPerPixel) return;
  Hit hit = trace(to_ray(rays[index]), false);
  hits[index] = HitRecord(hit.t, hit.patchIndex, hit.object, hit.st.x, hit.st.y, hit.geometricNormal.x,
                          hit.geometricNormal.y, hit.geometricNormal.z);
}

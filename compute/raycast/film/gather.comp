// Per camera ray, the radiance of its slot contributions (lights,
// environment, or what a miss sees; the shadow pass cleared those it found
// blocked), and whether it hit (in w). A pass of its own so that
// no invocation loops over a pixel's samples times their slots: lavapipe
// ends an invocation's loops after 65535 iterations in all.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/raycast_layout.h"
#include "compute/raycast/common/workgroup.glsl"

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 9, std430) readonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 15, std430) readonly buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 22, std430) writeonly buffer RayRadiance { vec4 rayRadiance[]; };

void main() {
  uint ray = invocation_index();
  if (ray >= frame.pixelCount * frame.raysPerPixel) return;
  vec3 radiance = vec3(0.0);
  for (uint slot = ray * frame.slotsPerRay; slot < (ray + 1u) * frame.slotsPerRay; ++slot)
    radiance += contributions[slot].xyz;
  rayRadiance[ray] = vec4(radiance, hits[ray].patchIndex == FACET_NO_HIT ? 0.0 : 1.0);
}

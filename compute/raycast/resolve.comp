// The beauty of each pixel: the mean over its shaded samples of the slot
// contributions (lights, environment, or what a miss sees) whose shadow rays
// reached their source or were never traced; alpha is the fraction of
// samples that hit.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/shared/raycast_layout.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 9, std430) readonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 15, std430) readonly buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 17, std430) readonly buffer ShadowHits { HitRecord shadowHits[]; };
layout(set = 0, binding = 18, std430) writeonly buffer Beauty { vec4 beauty[]; };

void main() {
  uint pixel = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u;
  if (pixel >= frame.pixelCount) return;
  uint first = frame.raysPerPixel == 1u ? 0u : 1u;
  vec3 radiance = vec3(0.0);
  float covered = 0.0;
  for (uint sample_index = first; sample_index < frame.raysPerPixel; ++sample_index) {
    uint ray = pixel * frame.raysPerPixel + sample_index;
    if (hits[ray].patchIndex != FACET_NO_HIT) covered += 1.0;
    for (uint slot = ray * frame.slotsPerRay; slot < (ray + 1u) * frame.slotsPerRay; ++slot)
      if (shadowHits[slot].patchIndex == FACET_NO_HIT) radiance += contributions[slot].xyz;
  }
  float samples = float(frame.strata * frame.strata);
  beauty[pixel] = vec4(radiance / samples, covered / samples);
}

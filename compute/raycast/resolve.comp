// The beauty of each pixel: the mean of its shaded samples' radiance (the
// gather pass's), and in alpha the fraction of them that hit.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/shared/raycast_layout.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 18, std430) writeonly buffer Beauty { vec4 beauty[]; };
layout(set = 0, binding = 22, std430) readonly buffer RayRadiance { vec4 rayRadiance[]; };

void main() {
  uint pixel = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u;
  if (pixel >= frame.pixelCount) return;
  uint first = frame.raysPerPixel == 1u ? 0u : 1u;
  vec4 sum = vec4(0.0);
  for (uint sample_index = first; sample_index < frame.raysPerPixel; ++sample_index)
    sum += rayRadiance[pixel * frame.raysPerPixel + sample_index];
  beauty[pixel] = sum / float(frame.strata * frame.strata);
}

// The beauty of each pixel from its shaded samples' radiance (the gather
// pass's), as rules/camera/sample_plan.h resolves it.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/raycast_layout.h"
#include "compute/raycast/common/workgroup.glsl"

#include "rules/language.glsl"
#include "rules/camera/sample_plan.h"

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 18, std430) writeonly buffer Beauty { vec4 beauty[]; };
layout(set = 0, binding = 22, std430) readonly buffer RayRadiance { vec4 rayRadiance[]; };

void main() {
  uint pixel = invocation_index();
  if (pixel >= frame.pixelCount) return;
  vec4 sum = vec4(0.0);
  for (uint sample_index = first_shaded_sample(frame.strata); sample_index < frame.raysPerPixel; ++sample_index)
    sum += rayRadiance[pixel * frame.raysPerPixel + sample_index];
  beauty[pixel] = sum / float(shaded_sample_count(frame.strata));
}

// One invocation: the shadow pass's workgroup grid from the number of
// shadow rays the surface pass appended (workgroups as invocation_index()
// expects them: at most 65535 along x).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/shared/raycast_layout.h"

layout(local_size_x = 1) in;

layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };

void main() {
  uint groups = (counters.shadowRays + 63u) / 64u;
  uint x = min(groups, 65535u);
  counters.dispatchX = x;
  counters.dispatchY = x == 0u ? 0u : (groups + x - 1u) / x;
  counters.dispatchZ = 1u;
}

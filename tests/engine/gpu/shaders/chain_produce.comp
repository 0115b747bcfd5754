#version 450
// First of two chained dispatches: writes values and the second dispatch's size.
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Produced { uint produced[]; };
layout(std430, binding = 1) writeonly buffer Indirect { uvec3 groups; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < produced.length()) produced[i] = i * 2654435761u;
  if (i == 0) groups = uvec3((produced.length() + 63) / 64, 1, 1);
}

#version 450
// Second dispatch: each invocation reads values written by other workgroups
// of the first, so it is only right if a barrier separates the two.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Produced { uint produced[]; };
layout(std430, binding = 1) writeonly buffer Consumed { uint consumed[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  uint n = produced.length();
  if (i < n) consumed[i] = produced[(i * 7919u + 13u) % n] ^ produced[n - 1u - i];
}

#version 450
// y = a·x + y: the smoke job that proves a device runs our SPIR-V correctly.
layout(local_size_x = 64) in;
layout(constant_id = 0) const float kA = 2.0;
layout(std430, set = 0, binding = 0) readonly buffer X { float x[]; };
layout(std430, set = 0, binding = 1) buffer Y { float y[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < y.length()) y[i] = kA * x[i] + y[i];
}

#version 450
// Dependent vec4 multiply-add chains: a known amount of arithmetic, for
// timestamp tests and the GFLOP/s benchmark. 16 flops per loop iteration.
layout(local_size_x = 64) in;
layout(constant_id = 0) const int kIterations = 1024;
layout(std430, binding = 0) buffer Values { vec4 values[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= values.length()) return;
  vec4 a = values[i];
  vec4 b = a * 0.5 + 0.25;
  for (int k = 0; k < kIterations; ++k) {
    a = a * b + vec4(0.001);
    b = b * a + vec4(-0.001);
  }
  values[i] = a + b;
}

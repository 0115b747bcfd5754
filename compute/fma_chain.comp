#version 450
// Multiply-add chains: a known amount of arithmetic, for timestamp tests and
// the GFLOP/s benchmark. Four independent pairs of chains give the compiler
// instruction-level parallelism; 64 flops per loop iteration.
layout(local_size_x = 64) in;
layout(constant_id = 0) const int kIterations = 256;
layout(std430, binding = 0) buffer Values { vec4 values[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= values.length()) return;
  vec4 a0 = values[i], a1 = a0 + 0.125, a2 = a0 + 0.25, a3 = a0 + 0.375;
  vec4 b0 = a0 * 0.5 + 0.25, b1 = a1 * 0.5 + 0.25, b2 = a2 * 0.5 + 0.25, b3 = a3 * 0.5 + 0.25;
  for (int k = 0; k < kIterations; ++k) {
    a0 = a0 * b0 + vec4(0.001);
    a1 = a1 * b1 + vec4(0.001);
    a2 = a2 * b2 + vec4(0.001);
    a3 = a3 * b3 + vec4(0.001);
    b0 = b0 * a0 + vec4(-0.001);
    b1 = b1 * a1 + vec4(-0.001);
    b2 = b2 * a2 + vec4(-0.001);
    b3 = b3 * a3 + vec4(-0.001);
  }
  values[i] = (a0 + b0) + (a1 + b1) + (a2 + b2) + (a3 + b3);
}

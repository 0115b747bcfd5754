#version 450
// Non-trivial but well-conditioned float math (all terms positive), so the
// host can hold the device to a few ULP.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 abc[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float result[]; };

float horner(float x) {
  return ((((0.5 * x + 1.25) * x + 0.75) * x + 2.0) * x + 0.125) * x + 3.0;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= result.length()) return;
  vec4 v = abc[i];
  result[i] = sqrt(v.x * v.x + v.y * v.y) + v.x / (1.0 + v.y) + horner(v.z) * inversesqrt(v.w);
}

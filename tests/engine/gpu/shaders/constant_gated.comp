#version 450
// A constant decides whether a whole function runs: folded in, it takes the
// function with it.
layout(local_size_x = 64) in;
layout(constant_id = 0) const bool kPolynomial = true;
layout(std430, binding = 0) buffer Values { float values[]; };

float polynomial(float x) {
  float sum = 0.0;
  for (int k = 0; k < 8; ++k) sum = sum * x + float(k);
  return sum;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= values.length()) return;
  if (kPolynomial) values[i] = polynomial(values[i]);
}

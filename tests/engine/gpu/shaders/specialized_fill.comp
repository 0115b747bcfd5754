#version 450
// Both the arithmetic and the workgroup size come from specialization constants.
layout(local_size_x_id = 0) in;
layout(constant_id = 1) const int kMode = 0;
layout(constant_id = 2) const float kScale = 1.0;
layout(constant_id = 3) const bool kNegate = false;
layout(std430, binding = 0) writeonly buffer Outputs { float values[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= values.length()) return;
  float v = kMode == 0 ? float(i) * kScale : float(i * i) + kScale;
  values[i] = kNegate ? -v : v;
}

#version 450
// Buffers in two bind groups, so a test can switch to a pipeline whose group 0
// layout differs while group 1 stays bound.
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) writeonly buffer Outputs { uint outputs[]; };
layout(std430, set = 1, binding = 0) readonly buffer Inputs { uint inputs[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < inputs.length()) outputs[i] = inputs[i] + 1u;
}

#version 450
// Push constants are a Vulkan feature WebGPU (and so facet::gpu) leaves out.
layout(local_size_x = 1) in;
layout(push_constant) uniform Constants { float scale; } constants;
layout(std430, binding = 0) buffer Values { float values[]; };

void main() { values[0] *= constants.scale; }

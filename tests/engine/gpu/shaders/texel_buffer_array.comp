#version 450
// An array of texel buffers at one binding: facet::gpu binds one buffer per binding.
layout(local_size_x = 1) in;
layout(binding = 0) uniform usamplerBuffer tables[2];
layout(std430, binding = 1) writeonly buffer Outputs { uvec4 outputs[]; };

void main() { outputs[0] = texelFetch(tables[1], 0); }

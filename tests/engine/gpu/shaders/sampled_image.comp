#version 450
// A sampled image: a binding facet::gpu does not support (buffers only).
layout(local_size_x = 1) in;
layout(binding = 0) uniform sampler2D image;
layout(std430, binding = 1) buffer Outputs { vec4 outputs[]; };

void main() { outputs[0] = texelFetch(image, ivec2(0), 0); }

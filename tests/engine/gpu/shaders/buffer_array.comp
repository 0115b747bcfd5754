#version 450
// An array of buffers at one binding: facet::gpu binds one buffer per binding.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Values { float values[]; } blocks[4];

void main() { blocks[1].values[0] = 1.0; }

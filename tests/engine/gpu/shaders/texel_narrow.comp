#version 450
// A storage texel buffer of one 32-bit component: facet::gpu has only 4 x 32-bit texel formats.
layout(local_size_x = 1) in;
layout(binding = 0, r32ui) uniform writeonly uimageBuffer narrow;

void main() { imageStore(narrow, 0, uvec4(1u)); }

#version 450
// Fills a storage texel buffer with imageStore.
layout(local_size_x = 64) in;
layout(binding = 0, rgba32ui) uniform writeonly uimageBuffer texels;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uint(imageSize(texels))) imageStore(texels, int(i), uvec4(i * 2654435761u, ~i, i ^ 0x80000001u, 0xFFFFFFFFu));
}

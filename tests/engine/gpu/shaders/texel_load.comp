#version 450
#extension GL_EXT_samplerless_texture_functions : require
// A read-only storage texel buffer (imageLoad) and a texture buffer with no
// sampler: both texel bindings, both only read.
layout(local_size_x = 64) in;
layout(binding = 0, rgba32i) uniform readonly iimageBuffer signedTexels;
layout(binding = 1) uniform textureBuffer floatTexels;
layout(std430, binding = 2) writeonly buffer Outputs { ivec4 outputs[]; };

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i < imageSize(signedTexels)) outputs[i] = imageLoad(signedTexels, i) - ivec4(texelFetch(floatTexels, i));
}

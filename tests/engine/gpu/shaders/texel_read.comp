#version 450
// Uniform texel buffers: uint bit patterns, and floats through a float view
// and a uint view of the same buffer.
layout(local_size_x = 64) in;
layout(binding = 0) uniform usamplerBuffer patterns;
layout(binding = 1) uniform samplerBuffer floats;
layout(binding = 2) uniform usamplerBuffer floatBits;
layout(std430, binding = 3) writeonly buffer Outputs { uvec4 outputs[]; };

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= textureSize(patterns)) return;
  outputs[3 * i] = texelFetch(patterns, i);
  outputs[3 * i + 1] = floatBitsToUint(texelFetch(floats, i));
  outputs[3 * i + 2] = floatBitsToUint(uintBitsToFloat(texelFetch(floatBits, i)) * 2.0 + 1.0);
}

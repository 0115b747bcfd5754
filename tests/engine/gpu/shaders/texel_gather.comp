#version 450
// Reads a uniform texel buffer out of order, so texels cross workgroups.
layout(local_size_x = 64) in;
layout(binding = 0) uniform usamplerBuffer source;
layout(std430, binding = 1) writeonly buffer Outputs { uvec4 outputs[]; };

void main() {
  uint n = uint(textureSize(source));
  uint i = gl_GlobalInvocationID.x;
  if (i < n) outputs[i] = texelFetch(source, int((i * 7919u + 13u) % n));
}

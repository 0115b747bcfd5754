// Camera rays, one per pixel: the nearest hit's (t, triangle), (inf, EMPTY) on a miss.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "benchmarks/ceiling/ceiling.glsl"

layout(set = 0, binding = 3, std430) writeonly buffer Hits { uvec2 hits[]; };

void main() {
  uint pixel = gl_GlobalInvocationID.x;
  if (pixel >= pixel_count()) return;
  float t = INF;
  uint tri = trace(vec3(0.0), camera_direction(pixel), t, false);
  hits[pixel] = uvec2(floatBitsToUint(t), tri);
}

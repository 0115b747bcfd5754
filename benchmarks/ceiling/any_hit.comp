// Shadow rays from the camera rays' hits toward the point light. Per pixel:
// 0 no hit, 1 facing away from the light (not traced), 2 lit, 3 occluded.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "benchmarks/ceiling/ceiling.glsl"

layout(set = 0, binding = 3, std430) readonly buffer Hits { uvec2 hits[]; };
layout(set = 0, binding = 4, std430) writeonly buffer Shadow { uint shadow[]; };

void main() {
  uint pixel = gl_GlobalInvocationID.x;
  if (pixel >= pixel_count()) return;
  uvec2 hit = hits[pixel];
  if (hit.y == EMPTY) {
    shadow[pixel] = 0u;
    return;
  }
  vec3 d = camera_direction(pixel);
  vec3 p = d * uintBitsToFloat(hit.x);
  int base = int(hit.y) * 3;
  vec3 n = normalize(cross(texelFetch(tris, base + 1).xyz, texelFetch(tris, base + 2).xyz));
  if (dot(n, d) > 0.0) n = -n;
  if (dot(n, frame.light.xyz - p) <= 0.0) {
    shadow[pixel] = 1u;
    return;
  }
  // Off the surface along the normal, so the ray cannot hit its own triangle.
  vec3 o = p + n * frame.light.w;
  vec3 toLight = frame.light.xyz - o;
  float t = length(toLight);
  shadow[pixel] = trace(o, toLight / t, t, true) == EMPTY ? 2u : 3u;
}

// The irradiance map: per node, the cosine-weighted mean radiance around its
// direction over every texel of one level of the source map's mip chain
// (rules/environment/irradiance_map.h, as in the CPU reference).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/environment/environment_mapping.h"
#include "rules/environment/irradiance_map.h"
#include "rules/grid/config.h"

layout(local_size_x = FACET_IBL_TILE_SIZE, local_size_y = FACET_IBL_TILE_SIZE) in;

layout(set = 0, binding = 0, std140) uniform Params {
  int width;  // of the irradiance map
  int height;  // its rows of nodes, pole to pole
  int sourceWidth;  // of the chain level read
  int sourceHeight;
  uint sourceOffset;  // in floats
};
layout(set = 0, binding = 1, std430) readonly buffer Chain { float chain[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Irradiance { float irradiance[]; };

void main() {
  int x = int(gl_GlobalInvocationID.x);
  int y = int(gl_GlobalInvocationID.y);
  if (x >= width || y >= height) return;
  vec3 n = irradiance_node_direction(x, y, width, height);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int j = 0; j < sourceHeight; ++j) {
    float solidAngle = environment_texel_solid_angle(j, sourceWidth, sourceHeight);
    for (int i = 0; i < sourceWidth; ++i) {
      float w = irradiance_texel_weight(n, irradiance_texel_direction(i, j, sourceWidth, sourceHeight), solidAngle);
      uint t = sourceOffset + 3u * uint(j * sourceWidth + i);
      sum += w * vec3(chain[t], chain[t + 1u], chain[t + 2u]);
      weight += w;
    }
  }
  vec3 mean = sum / weight;
  uint o = 3u * uint(y * width + x);
  irradiance[o] = mean.x;
  irradiance[o + 1u] = mean.y;
  irradiance[o + 2u] = mean.z;
}

// One level of the source map's mip chain (prefilter.comp reads it): each
// texel the solid-angle-weighted mean of the four it covers one level finer
// (environment_upper_row_share). All levels share one buffer of 3 floats per
// texel, finest first.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/environment/prefilter.h"
#include "rules/grid/config.h"

layout(local_size_x = FACET_IBL_TILE_SIZE, local_size_y = FACET_IBL_TILE_SIZE) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint finerOffset;  // in floats
  uint coarserOffset;
  int coarserWidth;
  int coarserHeight;
};
layout(set = 0, binding = 1, std430) buffer Chain { float chain[]; };

vec3 finerTexel(int x, int y) {
  uint i = finerOffset + 3u * uint(y * 2 * coarserWidth + x);
  return vec3(chain[i], chain[i + 1u], chain[i + 2u]);
}

void main() {
  int x = int(gl_GlobalInvocationID.x);
  int y = int(gl_GlobalInvocationID.y);
  if (x >= coarserWidth || y >= coarserHeight) return;
  float upper = environment_upper_row_share(y, 2 * coarserHeight);
  vec3 mean = 0.5 * (upper * (finerTexel(2 * x, 2 * y) + finerTexel(2 * x + 1, 2 * y)) +
                     (1.0 - upper) * (finerTexel(2 * x, 2 * y + 1) + finerTexel(2 * x + 1, 2 * y + 1)));
  uint o = coarserOffset + 3u * uint(y * coarserWidth + x);
  chain[o] = mean.x;
  chain[o + 1u] = mean.y;
  chain[o + 2u] = mean.z;
}

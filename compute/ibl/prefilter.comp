// One prefiltered level: per texel, GGX filtered importance sampling around
// its direction r (n = v = r), each sample read trilinearly from the source
// map's mip chain at the level its density asks for (the math is
// rules/environment/prefilter.h's, as in the CPU reference).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/environment/environment_mapping.h"
#include "rules/environment/prefilter.h"
#include "rules/grid/config.h"
#include "rules/shading/microfacet.h"

layout(local_size_x = FACET_IBL_TILE_SIZE, local_size_y = FACET_IBL_TILE_SIZE) in;

layout(set = 0, binding = 0, std140) uniform Params {
  int width;  // of this level
  int height;
  float alpha;
  int samples;
  int sourceWidth;  // of the chain's finest level, the map itself
  int sourceHeight;
  int chainLevels;
  uint outputOffset;  // in floats
};
layout(set = 0, binding = 1, std430) readonly buffer Chain { float chain[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Levels { float levels[]; };

vec3 chainBilinear(int level, vec2 uv) {
  uint offset = 0u;
  int w = sourceWidth;
  int h = sourceHeight;
  for (int l = 0; l < level; ++l) {
    offset += 3u * uint(w * h);
    w /= 2;
    h /= 2;
  }
  BilinearTaps t = environment_bilinear(uv, w, h);
  uint i00 = offset + 3u * uint(t.y0 * w + t.x0);
  uint i10 = offset + 3u * uint(t.y0 * w + t.x1);
  uint i01 = offset + 3u * uint(t.y1 * w + t.x0);
  uint i11 = offset + 3u * uint(t.y1 * w + t.x1);
  vec3 top = mix(vec3(chain[i00], chain[i00 + 1u], chain[i00 + 2u]), vec3(chain[i10], chain[i10 + 1u], chain[i10 + 2u]), t.fx);
  vec3 bottom = mix(vec3(chain[i01], chain[i01 + 1u], chain[i01 + 2u]), vec3(chain[i11], chain[i11 + 1u], chain[i11 + 2u]), t.fx);
  return mix(top, bottom, t.fy);
}

void main() {
  int x = int(gl_GlobalInvocationID.x);
  int y = int(gl_GlobalInvocationID.y);
  if (x >= width || y >= height) return;
  vec3 r = environment_direction(vec2((float(x) + 0.5) / float(width), (float(y) + 0.5) / float(height)));
  Frame frame = frame_from_normal(r);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int k = 0; k < samples; ++k) {
    vec3 m = prefilter_sample_normal(k, samples, alpha);
    float w = prefilter_sample_weight(alpha, m);
    if (w <= 0.0) continue;
    float lod = prefilter_source_lod(alpha, m, samples, sourceWidth, sourceHeight, chainLevels);
    vec2 uv = environment_uv(reflect(-r, from_local(frame, m)));
    int l0 = min(int(floor(lod)), chainLevels - 1);
    int l1 = min(l0 + 1, chainLevels - 1);
    sum += w * mix(chainBilinear(l0, uv), chainBilinear(l1, uv), lod - float(l0));
    weight += w;
  }
  vec3 radiance = weight > 0.0 ? sum / weight : vec3(0.0);
  uint o = outputOffset + 3u * uint(y * width + x);
  levels[o] = radiance.x;
  levels[o + 1u] = radiance.y;
  levels[o + 2u] = radiance.z;
}

// The environment as the surface kernel sees it: radiance lookups, the
// luminance distribution of the sampled method, the prefiltered data of
// the split sum and the mip chain of the filtered method, laid out by FrameParams' offsets
// (engine/gpu_backend/gpu_renderer.cpp). The same steps as the CPU
// reference (engine/cpu/reference_renderer.cpp, engine/ibl/), in float.
// Needs `frame`.
#ifndef FACET_RAYCAST_ENVIRONMENT_GLSL
#define FACET_RAYCAST_ENVIRONMENT_GLSL

#include "rules/language.glsl"
#include "rules/environment/environment_mapping.h"
#include "rules/environment/irradiance_map.h"
#include "rules/environment/spherical_harmonics.h"
#include "rules/environment/split_sum.h"
#include "compute/raycast/shading/dfg_tables.glsl"

vec3 to_map(vec3 world) {
  return environment_to_map(world, frame.environmentCosRotation, frame.environmentSinRotation);
}

vec3 from_map(vec3 map_direction) {
  return environment_from_map(map_direction, frame.environmentCosRotation, frame.environmentSinRotation);
}

// Read as texel buffers: the fast path on lavapipe, and not bound by the
// storage binding limit.
// The map's texels (level 0).
layout(set = 0, binding = 19) uniform samplerBuffer environmentTexels;
// Per prefiltered level (or level of the filtered method's chain), where it
// starts and its size.
layout(set = 0, binding = 20) uniform usamplerBuffer environmentLevels;
// Per map texel, the sampled method's alias-table entry: keep probability
// and texel density as float bits, the other texel.
layout(set = 0, binding = 21) uniform usamplerBuffer environmentSampling;
// The prefiltered data (levels, SH, DFG) or the chain's levels, one vec4 per entry.
layout(set = 0, binding = 23) uniform samplerBuffer environmentTables;

// (first texel, width, height) of level `level`; level 0 is the map itself.
uvec3 level_extent(int level) {
  return level == 0 ? uvec3(0u, frame.environmentWidth, frame.environmentHeight)
                    : texelFetch(environmentLevels, level).xyz;
}

// RGB radiance and, for the filtered method with environment samples, the
// environment's density in w.
vec4 level_texel(int level, uvec3 extent, int x, int y) {
  int i = int(extent.x + uint(y) * extent.y + uint(x));
  return level == 0 ? texelFetch(environmentTexels, i) : texelFetch(environmentTables, i);
}

vec4 level_bilinear(int level, vec2 uv) {
  uvec3 extent = level_extent(level);
  BilinearTaps b = environment_bilinear(uv, int(extent.y), int(extent.z));
  vec4 top = level_texel(level, extent, b.x0, b.y0) * (1.0 - b.fx) + level_texel(level, extent, b.x1, b.y0) * b.fx;
  vec4 bottom = level_texel(level, extent, b.x0, b.y1) * (1.0 - b.fx) + level_texel(level, extent, b.x1, b.y1) * b.fx;
  return top * (1.0 - b.fy) + bottom * b.fy;
}

// Radiance arriving from world direction `world`.
vec3 environment_radiance(vec3 world) {
  return frame.environmentIntensity * level_bilinear(0, environment_uv(to_map(world))).rgb;
}

float texel_pdf(int x, int y) {
  return uintBitsToFloat(texelFetch(environmentSampling, int(uint(y) * frame.environmentWidth + uint(x))).y);
}

// A direction (map frame) drawn by luminance from the alias table
// (engine/ibl/environment_distribution.h); returns its density in .w.
vec4 sample_environment(uint texel_bits, vec3 u) {
  uint width = frame.environmentWidth;
  uint texel, low;
  umulExtended(texel_bits, width * frame.environmentHeight, texel, low);
  uvec4 entry = texelFetch(environmentSampling, int(texel));
  if (u.x >= uintBitsToFloat(entry.x)) texel = entry.z;
  int x = int(texel % width), y = int(texel / width);
  int height = int(frame.environmentHeight);
  float cos_top = environment_row_cos(y, height), cos_bottom = environment_row_cos(y + 1, height);
  vec3 d = environment_direction_cos((float(x) + u.y) / float(width), cos_top + u.z * (cos_bottom - cos_top));
  return vec4(d, texel_pdf(x, y));
}

float environment_pdf(vec3 map_direction) {
  vec2 uv = environment_uv(map_direction);
  int width = int(frame.environmentWidth), height = int(frame.environmentHeight);
  return texel_pdf(clamp(int(uv.x * float(width)), 0, width - 1), clamp(int(uv.y * float(height)), 0, height - 1));
}

// Between levels `level` and `level + 1` of the chain or the ladder, linearly.
vec4 levels_trilinear(vec2 uv, float level) {
  int count = int(frame.levelCount);
  int lower = min(int(floor(level)), count - 1);
  int upper = min(lower + 1, count - 1);
  return mix(level_bilinear(lower, uv), level_bilinear(upper, uv), level - float(lower));
}

// Split sum lookups (engine/ibl/prefiltered_environment.h has the layouts).
vec3 prefiltered_radiance(vec3 map_direction, float alpha) {
  return levels_trilinear(environment_uv(map_direction), prefiltered_level(alpha, int(frame.levelCount))).rgb;
}

// Filtered method: radiance arriving from world direction `world`, read from
// the map's mip chain at `lod` (engine/ibl/environment_mip_chain.h), and in
// w the environment's density read from its chain alike.
vec4 filtered_lookup(vec3 world, float lod) {
  vec4 texel = levels_trilinear(environment_uv(to_map(world)), lod);
  return vec4(frame.environmentIntensity * texel.rgb, texel.w);
}

vec2 dfg_lookup(uint table, float nv, float alpha) {
  uint size = frame.dfgSize;
  return dfg_table_lookup(environmentTables, frame.dfgOffset + table * size * size, int(size), nv, alpha);
}

// The irradiance table at frame.shOffset (layout in irradiance_map.h).
vec3 irradiance_texel(int i) { return texelFetch(environmentTables, int(frame.shOffset) + i).rgb; }

vec3 irradiance_map_bilinear(vec2 uv, int width, int height) {
  IrradianceTaps t = irradiance_map_taps(uv, width, height);
  vec3 top = mix(irradiance_texel(irradiance_map_texel(t.t00)), irradiance_texel(irradiance_map_texel(t.t10)), t.fx);
  vec3 bottom = mix(irradiance_texel(irradiance_map_texel(t.t01)), irradiance_texel(irradiance_map_texel(t.t11)), t.fx);
  return mix(top, bottom, t.fy);
}

// E / pi at the normal: from the cosine-convolved map where the prefilter's
// rule chose it, else from the SH bands 0-2, clamped where they ring.
vec3 irradiance_over_pi(vec3 map_normal) {
  vec3 header = irradiance_texel(0);
  if (int(header.x) == IRRADIANCE_FROM_MAP)
    return irradiance_map_bilinear(environment_uv(map_normal), int(header.y), int(header.z));
  vec3 sum = vec3(0.0);
  for (int i = 0; i < 9; ++i) sum += irradiance_texel(irradiance_sh_texel(i)) * (sh_cosine_band(i) * sh_basis(i, map_normal));
  return max(sum, vec3(0.0));
}

#endif

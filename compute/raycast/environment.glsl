// The environment as the surface kernel sees it: radiance lookups, the
// luminance distribution of the sampled method and the prefiltered data of
// the split sum, all in one float buffer laid out by FrameParams' offsets
// (engine/gpu_backend/gpu_renderer.cpp). The same steps as the CPU
// reference (engine/cpu/reference_renderer.cpp, engine/ibl/), in float.
// Needs materials/shading.glsl, compute/shared/environment.h and `frame`.
#ifndef FACET_RAYCAST_ENVIRONMENT_GLSL
#define FACET_RAYCAST_ENVIRONMENT_GLSL

layout(set = 0, binding = 19, std430) readonly buffer EnvironmentData { float environment[]; };
layout(set = 0, binding = 20, std430) readonly buffer EnvironmentLevels { EnvironmentLevel levels[]; };
layout(set = 0, binding = 21, std430) readonly buffer EnvironmentAliases { uint aliases[]; };

vec3 to_map(vec3 world) {
  return environment_to_map(world, frame.environmentCosRotation, frame.environmentSinRotation);
}

vec3 from_map(vec3 map_direction) {
  return environment_from_map(map_direction, frame.environmentCosRotation, frame.environmentSinRotation);
}

vec3 level_texel(EnvironmentLevel level, int x, int y) {
  uint i = level.offset + 3u * (uint(y) * level.width + uint(x));
  return vec3(environment[i], environment[i + 1u], environment[i + 2u]);
}

vec3 level_bilinear(EnvironmentLevel level, vec2 uv) {
  BilinearTaps b = environment_bilinear(uv, int(level.width), int(level.height));
  vec3 top = level_texel(level, b.x0, b.y0) * (1.0 - b.fx) + level_texel(level, b.x1, b.y0) * b.fx;
  vec3 bottom = level_texel(level, b.x0, b.y1) * (1.0 - b.fx) + level_texel(level, b.x1, b.y1) * b.fx;
  return top * (1.0 - b.fy) + bottom * b.fy;
}

EnvironmentLevel environment_map_level() {
  EnvironmentLevel map;
  map.offset = 0u;
  map.width = frame.environmentWidth;
  map.height = frame.environmentHeight;
  map.alpha = 0.0;
  return map;
}

// Radiance arriving from world direction `world`.
vec3 environment_radiance(vec3 world) {
  return frame.environmentIntensity * level_bilinear(environment_map_level(), environment_uv(to_map(world)));
}

float texel_pdf(int x, int y) {
  return environment[frame.texelPdfOffset + uint(y) * frame.environmentWidth + uint(x)];
}

// A direction (map frame) drawn by luminance from the alias table
// (engine/ibl/environment_distribution.h); returns its density in .w.
vec4 sample_environment(vec4 u) {
  uint width = frame.environmentWidth, count = width * frame.environmentHeight;
  uint texel = min(uint(u.x * float(count)), count - 1u);
  if (u.y >= environment[frame.keepOffset + texel]) texel = aliases[texel];
  int x = int(texel % width), y = int(texel / width);
  int height = int(frame.environmentHeight);
  float cos_top = environment_row_cos(y, height), cos_bottom = environment_row_cos(y + 1, height);
  vec3 d = environment_direction_cos((float(x) + u.z) / float(width), cos_top + u.w * (cos_bottom - cos_top));
  return vec4(d, texel_pdf(x, y));
}

float environment_pdf(vec3 map_direction) {
  vec2 uv = environment_uv(map_direction);
  int width = int(frame.environmentWidth), height = int(frame.environmentHeight);
  return texel_pdf(clamp(int(uv.x * float(width)), 0, width - 1), clamp(int(uv.y * float(height)), 0, height - 1));
}

// Split sum lookups (engine/ibl/prefiltered_environment.h has the layouts).
vec3 prefiltered_radiance(vec3 map_direction, float alpha) {
  int count = int(frame.levelCount);
  float level = prefiltered_level(alpha, count);
  int lower = min(int(floor(level)), count - 1);
  int upper = min(lower + 1, count - 1);
  vec2 uv = environment_uv(map_direction);
  vec3 a = level_bilinear(levels[lower], uv);
  vec3 b = level_bilinear(levels[upper], uv);
  return mix(a, b, level - float(lower));
}

vec2 dfg_entry(uint table, int i, int j) {
  uint size = frame.dfgSize;
  uint k = frame.dfgOffset + 2u * (table * size * size + uint(j) * size + uint(i));
  return vec2(environment[k], environment[k + 1u]);
}

vec2 dfg_lookup(uint table, float nv, float alpha) {
  int size = int(frame.dfgSize);
  vec2 position = dfg_grid_position(nv, alpha, size);
  int i0 = int(floor(position.x)), j0 = int(floor(position.y));
  int i1 = min(i0 + 1, size - 1), j1 = min(j0 + 1, size - 1);
  float fx = position.x - float(i0), fy = position.y - float(j0);
  return mix(mix(dfg_entry(table, i0, j0), dfg_entry(table, i1, j0), fx),
             mix(dfg_entry(table, i0, j1), dfg_entry(table, i1, j1), fx), fy);
}

vec3 irradiance_over_pi(vec3 map_normal) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < 9; ++i) {
    uint k = frame.shOffset + 3u * uint(i);
    sum += vec3(environment[k], environment[k + 1u], environment[k + 2u]) * (sh_cosine_band(i) * sh_basis(i, map_normal));
  }
  return max(sum, vec3(0.0));
}

#endif

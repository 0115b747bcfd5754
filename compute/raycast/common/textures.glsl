// The scene's textures as the surface kernel reads them
// (engine/gpu_backend/texture_data.h): the same lookup as the CPU reference
// (scenes/texture.cpp), in float.
#ifndef FACET_RAYCAST_TEXTURES_GLSL
#define FACET_RAYCAST_TEXTURES_GLSL

#include "rules/language.glsl"
#include "rules/shading/textured_material.h"
#include "rules/texture/texture_sampling.h"

// Every level of every texture, linear RGBA.
layout(set = 0, binding = 29) uniform samplerBuffer textureTexels;
// Per level, (first texel, width, height, 0).
layout(set = 0, binding = 30) uniform usamplerBuffer textureLevels;
// Per texture, (first level, level count, wrap S, wrap T) then
// (mag filter, min filter, mip mode, 0).
layout(set = 0, binding = 31) uniform usamplerBuffer textureTable;

vec4 level_value(uvec4 level, TexelTaps taps) {
  int first = int(level.x), width = int(level.y);
  vec4 a = texelFetch(textureTexels, first + taps.y0 * width + taps.x0);
  vec4 b = texelFetch(textureTexels, first + taps.y0 * width + taps.x1);
  vec4 c = texelFetch(textureTexels, first + taps.y1 * width + taps.x0);
  vec4 d = texelFetch(textureTexels, first + taps.y1 * width + taps.x1);
  return mix(mix(a, b, taps.fx), mix(c, d, taps.fx), taps.fy);
}

vec4 level_lookup(uvec4 addressing, int level, vec2 uv, uint texel_filter) {
  uvec4 extent = texelFetch(textureLevels, int(addressing.x) + level);
  return level_value(extent, texel_taps(uv, int(extent.y), int(extent.z), texel_filter, addressing.z, addressing.w));
}

// The value of the slot's texture where the footprint `f` reads it; 1 for
// an empty slot, so that its factor stands alone.
vec4 slot_value(TextureSlotRecord slot, TextureFootprint f) {
  if (slot.texture == FACET_NO_TEXTURE) return vec4(1.0);
  uvec4 addressing = texelFetch(textureTable, int(2u * slot.texture));
  uvec4 filtering = texelFetch(textureTable, int(2u * slot.texture + 1u));
  uvec4 base = texelFetch(textureLevels, int(addressing.x));
  SlotLookup l = slot_lookup(f, vec2(slot.offsetX, slot.offsetY), slot.cosRotation, slot.sinRotation,
                             vec2(slot.scaleX, slot.scaleY), int(base.y), int(base.z));
  MipTaps mip = mip_taps(l.lod, int(addressing.y), filtering.x, filtering.y, filtering.z);
  vec4 first = level_lookup(addressing, mip.level0, l.uv, mip.texel_filter);
  return mip.blend > 0.0 ? mix(first, level_lookup(addressing, mip.level1, l.uv, mip.texel_filter), mip.blend) : first;
}

#endif

// A texture as plain data: linear RGBA texels decoded at load, their mip
// chain, and the glTF sampler that reads them. Knows no GPU; the lookup
// both backends share is rules/texture/texture_sampling.h.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "materials/material.h"
#include "rules/rules.h"

namespace facet::scene {

// One level of the chain, row-major from the image's first row (v = 0).
struct TextureLevel {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> texels;
};

// Codes of rules/texture/texture_sampling.h; the defaults are what glTF
// viewers use when a texture has no sampler.
struct TextureSampler {
  std::uint32_t wrapS = rules::f64::FACET_WRAP_REPEAT;
  std::uint32_t wrapT = rules::f64::FACET_WRAP_REPEAT;
  std::uint32_t magFilter = rules::f64::FACET_FILTER_LINEAR;
  std::uint32_t minFilter = rules::f64::FACET_FILTER_LINEAR;
  std::uint32_t mipMode = rules::f64::FACET_MIP_LINEAR;
};

struct Texture {
  std::string source;                // the image file, or what named it
  std::vector<TextureLevel> levels;  // level 0, then each half the size, down to 1 x 1
  TextureSampler sampler;
};

// Colour textures (base colour, emission, c_diff, F(0)) hold sRGB-encoded
// colour; data textures (metallic-roughness, normals, occlusion) hold
// values as they are. Alpha is linear either way.
enum class TextureEncoding { Linear, Srgb };

// The largest side of a texture image, whichever file names it.
inline constexpr int kMaxTextureSize = 16384;

// The largest magnitude of a texture coordinate scale (KHR_texture_transform's
// scale, glTF's normalTexture.scale). The GPU computes in float and multiplies
// two scaled partials (the level of detail, the normal map's frame): past
// about 1e19, the square root of float's range, that overflows and the
// backends part. Within 1e6 it stays far
// inside float's range, and a coordinate a million repeats long still keeps
// a few bits of its position within one repeat.
inline constexpr double kMaxTextureScale = 1e6;

// A texture from width x height texels of `components` channels (1 grey, 2
// grey and alpha, 3 RGB, 4 RGBA), each normalized to [0, 1]; builds the
// chain with a 2 x 2 box filter of the linear values.
Texture makeTexture(std::string source, int width, int height, int components, const std::vector<float>& channels,
                    TextureEncoding encoding, const TextureSampler& sampler);

// Textures from image files (PNG or JPEG, scenes/image_decoder.h); both
// throw InputError naming the file when it cannot be decoded. A colour
// texture decodes through the sRGB curve; a roughness texture holds the
// file's first channel in G, and 1 in R and B, the layout of glTF's
// metallic-roughness texture.
Texture loadColorTexture(const std::filesystem::path& file, const TextureSampler& sampler);
Texture loadRoughnessTexture(const std::filesystem::path& file, const TextureSampler& sampler);

// The filtered value at texture coordinates `uv` and level of detail `lod`
// (rules/texture/texture_sampling.h), in double.
glm::dvec4 sampleTexture(const Texture& texture, const glm::dvec2& uv, double lod);

// The value of a material's slot where footprint `f` reads it, among the
// scene's `textures`; 1 for an empty slot.
glm::dvec4 sampleSlot(const std::vector<Texture>& textures, const materials::TextureSlot& slot,
                      const rules::f64::TextureFootprint& f);

}  // namespace facet::scene

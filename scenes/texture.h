// A texture as plain data: linear RGBA texels decoded at load, their mip
// chain, and the glTF sampler that reads them. Knows no GPU; the lookup
// both backends share is rules/texture/texture_sampling.h.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
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

  bool operator==(const TextureSampler&) const = default;
};

// A texture's levels: level 0, then each half the size, down to 1 x 1.
// Immutable once built and shared by every copy of its scene (the adaptive
// rounds', the ground's, the APIs' scene values), so that copying a scene
// copies no texel, and a backend can keep what it made of a chain for as
// long as the same chain is rendered (sameChain).
class TextureChain {
 public:
  TextureChain() = default;
  explicit TextureChain(std::vector<TextureLevel> levels)
      : levels_(std::make_shared<const std::vector<TextureLevel>>(std::move(levels))) {}

  std::size_t size() const { return all().size(); }
  const TextureLevel& operator[](std::size_t level) const { return all()[level]; }
  std::vector<TextureLevel>::const_iterator begin() const { return all().begin(); }
  std::vector<TextureLevel>::const_iterator end() const { return all().end(); }
  // Whether both are the same chain, not merely equal texels.
  bool sameChain(const TextureChain& other) const { return levels_ == other.levels_; }

 private:
  const std::vector<TextureLevel>& all() const {
    static const std::vector<TextureLevel> none;
    return levels_ ? *levels_ : none;
  }

  std::shared_ptr<const std::vector<TextureLevel>> levels_;
};

struct Texture {
  std::string source;  // the image file, or what named it
  TextureChain levels;
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

// Whether `a` and `b` are the same chains under the same samplers, in the
// same order: what a backend made of `a` serves `b`.
bool sameTextures(const std::vector<Texture>& a, const std::vector<Texture>& b);

}  // namespace facet::scene

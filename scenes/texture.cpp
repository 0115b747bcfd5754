#include "scenes/texture.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "rules/rules.h"
#include "scenes/image_decoder.h"

namespace facet::scene {

namespace m = rules::f64;

namespace {

TextureLevel halve(const TextureLevel& level) {
  TextureLevel half;
  half.width = std::max(1, level.width / 2);
  half.height = std::max(1, level.height / 2);
  half.texels.resize(std::size_t(half.width) * std::size_t(half.height));
  auto at = [&](int x, int y) {
    return level.texels[std::size_t(std::min(y, level.height - 1)) * std::size_t(level.width) +
                        std::size_t(std::min(x, level.width - 1))];
  };
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x)
      half.texels[std::size_t(y) * std::size_t(half.width) + std::size_t(x)] =
          0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
  return half;
}

glm::dvec4 levelValue(const TextureLevel& level, const m::TexelTaps& taps) {
  auto at = [&](int x, int y) {
    return glm::dvec4(level.texels[std::size_t(y) * std::size_t(level.width) + std::size_t(x)]);
  };
  return glm::mix(glm::mix(at(taps.x0, taps.y0), at(taps.x1, taps.y0), taps.fx),
                  glm::mix(at(taps.x0, taps.y1), at(taps.x1, taps.y1), taps.fx), taps.fy);
}

}  // namespace

Texture makeTexture(std::string source, int width, int height, int components, const std::vector<float>& channels,
                    TextureEncoding encoding, const TextureSampler& sampler) {
  Texture texture;
  texture.source = std::move(source);
  texture.sampler = sampler;
  TextureLevel base;
  base.width = width;
  base.height = height;
  base.texels.resize(std::size_t(width) * std::size_t(height));
  auto colour = [&](float c) { return encoding == TextureEncoding::Srgb ? float(m::srgb_to_linear(c)) : c; };
  for (std::size_t i = 0; i < base.texels.size(); ++i) {
    const float* c = &channels[i * std::size_t(components)];
    const bool grey = components <= 2;
    const float alpha = components == 2 ? c[1] : components == 4 ? c[3] : 1.0f;
    base.texels[i] =
        grey ? glm::vec4(glm::vec3(colour(c[0])), alpha) : glm::vec4(colour(c[0]), colour(c[1]), colour(c[2]), alpha);
  }
  std::vector<TextureLevel> levels;
  levels.push_back(std::move(base));
  while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(halve(levels.back()));
  texture.levels = TextureChain(std::move(levels));
  return texture;
}

Texture loadColorTexture(const std::filesystem::path& file, const TextureSampler& sampler) {
  const DecodedImage image = decodeImage(file, kMaxTextureSize);
  return makeTexture(file.string(), image.width, image.height, image.components, image.channels, TextureEncoding::Srgb,
                     sampler);
}

Texture loadRoughnessTexture(const std::filesystem::path& file, const TextureSampler& sampler) {
  const DecodedImage image = decodeImage(file, kMaxTextureSize);
  std::vector<float> rgb;
  rgb.reserve(image.channels.size() / std::size_t(image.components) * 3);
  for (std::size_t i = 0; i < image.channels.size(); i += std::size_t(image.components))
    rgb.insert(rgb.end(), {1.0f, image.channels[i], 1.0f});
  return makeTexture(file.string(), image.width, image.height, 3, rgb, TextureEncoding::Linear, sampler);
}

glm::dvec4 sampleTexture(const Texture& texture, const glm::dvec2& uv, double lod) {
  const TextureSampler& s = texture.sampler;
  const m::MipTaps mip = m::mip_taps(lod, int(texture.levels.size()), s.magFilter, s.minFilter, s.mipMode);
  auto read = [&](int l) {
    const TextureLevel& level = texture.levels[std::size_t(l)];
    return levelValue(level, m::texel_taps(uv, level.width, level.height, mip.texel_filter, s.wrapS, s.wrapT));
  };
  const glm::dvec4 first = read(mip.level0);
  return mip.blend > 0 ? glm::mix(first, read(mip.level1), mip.blend) : first;
}

glm::dvec4 sampleSlot(const std::vector<Texture>& textures, const materials::TextureSlot& slot,
                      const m::TextureFootprint& f) {
  if (slot.texture < 0) return glm::dvec4(1.0);
  const Texture& texture = textures[std::size_t(slot.texture)];
  const m::SlotLookup l = m::slot_lookup(f, slot.offset, std::cos(slot.rotation), std::sin(slot.rotation), slot.scale,
                                         texture.levels[0].width, texture.levels[0].height);
  return sampleTexture(texture, l.uv, l.lod);
}

bool sameTextures(const std::vector<Texture>& a, const std::vector<Texture>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Texture& x, const Texture& y) {
    return x.levels.sameChain(y.levels) && x.sampler == y.sampler;
  });
}

}  // namespace facet::scene

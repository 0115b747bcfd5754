#include "engine/gpu_backend/texture_data.h"

#include <cmath>

namespace facet::gpu_backend {

TextureData textureData(const std::vector<scene::Texture>& textures) {
  TextureData data;
  // The texels run to hundreds of MiB: one allocation, not a doubling series of copies.
  std::size_t texels = 0;
  for (const scene::Texture& texture : textures)
    for (const scene::TextureLevel& level : texture.levels) texels += level.texels.size();
  data.texels.reserve(texels);
  for (const scene::Texture& texture : textures) {
    const scene::TextureSampler& s = texture.sampler;
    data.textures.push_back(
        {std::uint32_t(data.levels.size()), std::uint32_t(texture.levels.size()), s.wrapS, s.wrapT});
    data.textures.push_back({s.magFilter, s.minFilter, s.mipMode, 0});
    for (const scene::TextureLevel& level : texture.levels) {
      data.levels.push_back(
          {std::uint32_t(data.texels.size()), std::uint32_t(level.width), std::uint32_t(level.height), 0});
      data.texels.insert(data.texels.end(), level.texels.begin(), level.texels.end());
    }
  }
  return data;
}

gpu_layout::TextureSlotRecord textureSlotRecord(const materials::TextureSlot& slot) {
  return {slot.texture < 0 ? gpu_layout::FACET_NO_TEXTURE : std::uint32_t(slot.texture),
          float(slot.offset.x),
          float(slot.offset.y),
          float(std::cos(slot.rotation)),
          float(std::sin(slot.rotation)),
          float(slot.scale.x),
          float(slot.scale.y),
          std::uint32_t(slot.texCoord)};
}

}  // namespace facet::gpu_backend

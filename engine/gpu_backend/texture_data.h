// A scene's textures as compute/raycast/common/textures.glsl reads them: every
// level of every texture in one texel buffer, the levels' extents and each
// texture's sampler in two small tables.
#pragma once

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

#include "engine/gpu_backend/raycast_layout.h"
#include "scenes/texture.h"

namespace facet::gpu_backend {

struct TextureData {
  std::vector<glm::vec4> texels;  // linear RGBA, level after level, texture after texture
  std::vector<Texel> levels;      // per level: (first texel, width, height, 0)
  // Per texture, two entries: (first level, level count, wrap S, wrap T),
  // (mag filter, min filter, mip mode, 0).
  std::vector<Texel> textures;
};

TextureData textureData(const std::vector<scene::Texture>& textures);

// The record of a material's texture slot.
gpu_layout::TextureSlotRecord textureSlotRecord(const materials::TextureSlot& slot);

}  // namespace facet::gpu_backend

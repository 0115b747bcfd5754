#pragma once
// A glTF quad with every face-varying channel facet reads, made by the tests
// themselves: TEXCOORD_0, a TEXCOORD_1 that mirrors u, and COLOR_0 red,
// green, blue and white at its four corners, seen head-on by a camera that
// carries a directional light.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/textured_gltf.h"

namespace facet::testing {

// The accessors of writeChannelQuad's file: 0 POSITION, 1 TEXCOORD_0 (u from
// 0 at x = -1 to 1 at x = 1, v down the image), 2 TEXCOORD_1 (u mirrored),
// 3 COLOR_0 as VEC4 of FLOAT, 4 the same colours as normalized VEC4 of
// UNSIGNED_BYTE, 5 the six indices, 6 the colours as VEC3 of FLOAT.
inline nlohmann::json channelQuadAccessors() {
  const nlohmann::json textured = texturedQuadAccessors();  // POSITION and TEXCOORD_0 on views 0 and 1
  return {textured[0],
          textured[1],
          {{"bufferView", 2}, {"componentType", 5126}, {"type", "VEC2"}, {"count", 4}},
          {{"bufferView", 3}, {"componentType", 5126}, {"type", "VEC4"}, {"count", 4}},
          {{"bufferView", 4}, {"componentType", 5121}, {"normalized", true}, {"type", "VEC4"}, {"count", 4}},
          {{"bufferView", 5}, {"componentType", 5123}, {"type", "SCALAR"}, {"count", 6}},
          {{"bufferView", 3}, {"componentType", 5126}, {"type", "VEC3"}, {"count", 4}}};
}

// The quad from (-1, -1, 0) to (1, 1, 0) facing +z, corners red (-1, -1),
// green (1, -1), blue (1, 1) and white (-1, 1), with the primitive
// `attributes` (accessor indices above) in material 0, under a camera at
// (0, 0, 3) looking down -z whose node carries a directional light along
// -z; `parts` adds to or replaces the file's members.
inline std::filesystem::path writeChannelQuad(const std::filesystem::path& dir, const std::string& name,
                                              const nlohmann::json& attributes, const nlohmann::json& parts) {
  const float positions[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const float uv0[] = {0, 1, 1, 1, 1, 0, 0, 0};
  const float uv1[] = {1, 1, 0, 1, 0, 0, 1, 0};
  const float colours[] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
  const std::uint8_t bytes8[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::vector<char> bytes;
  nlohmann::json views = nlohmann::json::array();
  const auto add = [&](const void* data, std::size_t size) {
    views.push_back({{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", size}});
    bytes.insert(bytes.end(), static_cast<const char*>(data), static_cast<const char*>(data) + size);
  };
  add(positions, sizeof positions);
  add(uv0, sizeof uv0);
  add(uv1, sizeof uv1);
  add(colours, sizeof colours);
  views.back()["byteStride"] = 16;
  add(bytes8, sizeof bytes8);
  add(indices, sizeof indices);
  std::ofstream(dir / (name + ".bin"), std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  nlohmann::json file = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "directional"}, {"intensity", 3.0}}}}}}}},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes",
       {{{"mesh", 0}},
        {{"camera", 0}, {"translation", {0.0, 0.0, 3.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
      {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.01}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", 5}, {"material", 0}}}}}}},
      {"materials",
       {{{"doubleSided", true}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}}}},
      {"accessors", channelQuadAccessors()},
      {"bufferViews", views},
      {"buffers", {{{"uri", name + ".bin"}, {"byteLength", bytes.size()}}}}};
  if (!parts.is_null()) file.update(parts);
  std::ofstream(dir / (name + ".gltf")) << file.dump(1);
  return dir / (name + ".gltf");
}

}  // namespace facet::testing

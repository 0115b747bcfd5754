#pragma once
// Textured glTF scenes the tests make themselves: PNG images written with
// stb_image_write (facet_image compiles it) and a quad with TEXCOORD_0 whose
// materials, textures, samplers and images the caller gives.

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace facet::testing {

struct Rgba8 {
  std::uint8_t r, g, b, a;
};

// A size x size image of cells x cells squares of `even` and `odd`.
inline std::vector<Rgba8> checkerTexels(int size, int cells, Rgba8 even, Rgba8 odd) {
  std::vector<Rgba8> texels;
  const int cell = size / cells;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) texels.push_back(((x / cell + y / cell) % 2 == 0) ? even : odd);
  return texels;
}

inline bool writePng(const std::filesystem::path& file, int width, int height, const std::vector<Rgba8>& texels) {
  return stbi_write_png(file.c_str(), width, height, 4, texels.data(), width * 4) != 0;
}

// The accessors of writeTexturedQuad's file: POSITION, TEXCOORD_0 and the
// six indices of its two triangles (lower right, then upper left).
inline nlohmann::json texturedQuadAccessors() {
  return {{{"bufferView", 0},
           {"componentType", 5126},
           {"type", "VEC3"},
           {"count", 4},
           {"min", {-1, -1, 0}},
           {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"type", "VEC2"}, {"count", 4}},
          {{"bufferView", 2}, {"componentType", 5123}, {"type", "SCALAR"}, {"count", 6}}};
}

// A glTF file of one quad from (-1, -1, 0) to (1, 1, 0) facing +z, its
// TEXCOORD_0 (0, 0) at the top-left corner (-1, 1) and (1, 1) at (1, -1), in
// material 0; `parts` adds its members ("materials", "textures", ...) to
// the file's.
inline std::filesystem::path writeTexturedQuad(const std::filesystem::path& dir, const std::string& name,
                                               const nlohmann::json& parts) {
  const float positions[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};
  const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::vector<char> bytes(sizeof positions + sizeof uvs + sizeof indices);
  std::memcpy(bytes.data(), positions, sizeof positions);
  std::memcpy(bytes.data() + sizeof positions, uvs, sizeof uvs);
  std::memcpy(bytes.data() + sizeof positions + sizeof uvs, indices, sizeof indices);
  std::ofstream(dir / (name + ".bin"), std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  nlohmann::json file = {
      {"asset", {{"version", "2.0"}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}}}}}}},
      {"accessors", texturedQuadAccessors()},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof positions}},
        {{"buffer", 0}, {"byteOffset", sizeof positions}, {"byteLength", sizeof uvs}},
        {{"buffer", 0}, {"byteOffset", sizeof positions + sizeof uvs}, {"byteLength", sizeof indices}}}},
      {"buffers", {{{"uri", name + ".bin"}, {"byteLength", bytes.size()}}}}};
  file.update(parts);
  std::ofstream(dir / (name + ".gltf")) << file.dump(1);
  return dir / (name + ".gltf");
}

// `parts` of writeTexturedQuad's file (written as `name`) with the quad's
// NORMALs (+z) and, where given, one TANGENT for every vertex, from a second
// buffer written beside the quad's.
inline nlohmann::json withQuadNormals(nlohmann::json parts, const std::filesystem::path& dir, const std::string& name,
                                      std::optional<std::array<float, 4>> tangent) {
  const float normals[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::ofstream out(dir / (name + "_frame.bin"), std::ios::binary);
  out.write(reinterpret_cast<const char*>(normals), sizeof normals);
  for (int v = 0; v < 4 && tangent; ++v) out.write(reinterpret_cast<const char*>(tangent->data()), 16);
  nlohmann::json accessors = texturedQuadAccessors();
  accessors.push_back({{"bufferView", 3}, {"componentType", 5126}, {"type", "VEC3"}, {"count", 4}});
  nlohmann::json attributes = {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"NORMAL", 3}};
  // The quad's views: positions (48 bytes), coordinates (32) and indices (12).
  nlohmann::json views = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                          {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
                          {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}},
                          {{"buffer", 1}, {"byteOffset", 0}, {"byteLength", sizeof normals}}};
  if (tangent) {
    accessors.push_back({{"bufferView", 4}, {"componentType", 5126}, {"type", "VEC4"}, {"count", 4}});
    views.push_back({{"buffer", 1}, {"byteOffset", sizeof normals}, {"byteLength", 64}});
    attributes["TANGENT"] = 4;
  }
  parts["accessors"] = accessors;
  parts["bufferViews"] = views;
  parts["meshes"] = {{{"primitives", {{{"attributes", attributes}, {"indices", 2}, {"material", 0}}}}}};
  parts["buffers"] = {{{"uri", name + ".bin"}, {"byteLength", 92}},
                      {{"uri", name + "_frame.bin"}, {"byteLength", sizeof normals + (tangent ? 64 : 0)}}};
  return parts;
}

}  // namespace facet::testing

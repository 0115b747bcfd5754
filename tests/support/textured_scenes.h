#pragma once
// The textured scenes of the parity and aliasing tests: the quad of
// textured_gltf.h seen at an angle, with a base-colour checker that also
// emits, a metallic-roughness ramp and a normal map of ridges.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "tests/support/textured_gltf.h"

namespace facet::testing {

// A camera 3 units from the quad's centre, 60 degrees off its normal (+z),
// looking along +y and down.
inline nlohmann::json obliqueCamera(double degrees = 60.0) {
  const double half = 0.5 * degrees * std::numbers::pi / 180.0;
  const double a = 2.0 * half;
  return {{"nodes",
           {{{"mesh", 0}},
            {{"camera", 0},
             {"translation", {0.0, -3.0 * std::sin(a), 3.0 * std::cos(a)}},
             {"rotation", {std::sin(half), 0.0, 0.0, std::cos(half)}}}}},
          {"scenes", {{{"nodes", {0, 1}}}}},
          {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.01}}}}}}};
}

// A 64 x 64 normal map of ridges along v: the normal tilts by up to 35
// degrees towards +u and back.
inline std::vector<Rgba8> ridgeNormals() {
  std::vector<Rgba8> texels;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double tilt = 0.6 * std::sin(2.0 * std::numbers::pi * x / 16.0);
      const double nx = std::sin(tilt), nz = std::cos(tilt);
      texels.push_back(
          {std::uint8_t(std::lround(127.5 * (nx + 1.0))), 128, std::uint8_t(std::lround(127.5 * (nz + 1.0))), 255});
    }
  return texels;
}

// A 64 x 64 metallic-roughness ramp: roughness (G) across u, metallic (B) down v.
inline std::vector<Rgba8> metallicRoughnessRamp() {
  std::vector<Rgba8> texels;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) texels.push_back({0, std::uint8_t(64 + 2 * x), std::uint8_t(4 * y), 255});
  return texels;
}

// The textured quad of base colour, metallic-roughness, normal map (its R
// also the occlusion) and emission in `dir`, its base colour (and emission) checker (64 x 64 texels, `cells` squares a
// side) repeated `repeats` times across the quad and read with glTF minFilter `minFilter`.
inline std::filesystem::path writeTexturedScene(const std::filesystem::path& dir, const std::string& name, int cells,
                                                double repeats, int minFilter) {
  writePng(dir / "checker.png", 64, 64, checkerTexels(64, cells, {230, 200, 40, 255}, {20, 60, 180, 255}));
  writePng(dir / "metallic_roughness.png", 64, 64, metallicRoughnessRamp());
  writePng(dir / "normal.png", 64, 64, ridgeNormals());
  nlohmann::json parts = obliqueCamera();
  parts["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorTexture",
          {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {repeats, repeats}}}}}}}},
         {"metallicRoughnessTexture", {{"index", 1}}}}},
       {"normalTexture", {{"index", 2}, {"scale", 0.8}}},
       {"occlusionTexture", {{"index", 2}, {"strength", 0.7}}},
       {"emissiveTexture", {{"index", 0}}},
       {"emissiveFactor", {0.1, 0.05, 0.0}}}};
  parts["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}, {{"source", 2}}};
  parts["samplers"] = {{{"minFilter", minFilter}, {"magFilter", 9729}}};
  parts["images"] = {{{"uri", "checker.png"}}, {{"uri", "metallic_roughness.png"}}, {{"uri", "normal.png"}}};
  parts["extensionsUsed"] = {"KHR_texture_transform"};
  return writeTexturedQuad(dir, name, parts);
}

}  // namespace facet::testing

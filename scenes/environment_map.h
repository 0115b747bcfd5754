// Distant lighting as plain data: an equirectangular radiance map, from an
// OpenEXR file (any compression OpenEXR reads, DWAB included), a Radiance
// .hdr file, or a constant colour. Knows no renderer.
//
// Mapping (rules/environment/environment_mapping.h has the formulas both backends use):
// row 0 is the top (+y, theta = 0); u = 0.5 looks down -z; u grows towards
// +x. A map is 2:1 (width = 2 x height).
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace facet::scene {

// The GPU sums, filters and importance-samples a map in float: sums over
// the largest map (2^27 texels) stay finite below this radiance, which a
// loaded map's texels, and on the GPU their product with the intensity, may
// not exceed.
constexpr float kMaxEnvironmentRadiance = 1e30f;

struct EnvironmentMap {
  std::filesystem::path source;  // empty for a constant colour
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // linear radiance, row-major, 3 floats per texel
  // Texels that were negative, NaN or Inf in the file, set to 0 on load.
  std::size_t clampedTexels = 0;

  glm::vec3 texel(int x, int y) const {
    const float* p = &rgb[3 * (std::size_t(y) * std::size_t(width) + std::size_t(x))];
    return {p[0], p[1], p[2]};
  }
  // The largest channel of any texel.
  float largestRadiance() const;
  // A digest of the size and every texel: keys caches of what is derived
  // from the map, whatever file it came from.
  std::uint64_t contentHash() const;
};

// Reads `file` by its extension (.exr, .hdr). Throws InputError naming the
// file and the rule when it cannot be read, is not 2:1, is larger than
// 16384 x 8192, or holds a radiance above 1e30 (after negative, NaN and Inf
// texels are set to 0).
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& file);

// A uniform environment of radiance `color` (8 x 4 equal texels, so that
// every method treats it like any other map).
EnvironmentMap constantEnvironment(const glm::dvec3& color);

}  // namespace facet::scene

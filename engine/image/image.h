// The image both backends fill: beauty and every AOV, one plane each, row 0
// at the top. A pixel the camera ray misses has alpha 0, depth +inf, ids
// kNoId and zero elsewhere.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace facet {

struct Image {
  static constexpr std::uint32_t kNoId = 0xFFFFFFFFu;

  Image() = default;
  Image(int width, int height);

  int width = 0;
  int height = 0;
  std::vector<glm::vec4> beauty;           // linear RGB radiance, alpha = coverage
  std::vector<float> depth;                // distance from the eye along the ray
  std::vector<glm::vec3> position;         // world space
  std::vector<glm::vec3> geometricNormal;  // from the hit geometry, facing the eye
  std::vector<glm::vec3> shadingNormal;    // limit-surface normal
  std::vector<std::uint32_t> patchId;
  std::vector<std::uint32_t> faceId;  // control-cage face
  std::vector<glm::vec2> uv;          // on that face
  std::vector<glm::vec2> texcoord;    // texture coordinates (0 where the surface has none)

  std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
  std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
};

}  // namespace facet

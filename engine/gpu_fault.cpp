#include "engine/gpu_fault.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <utility>

namespace facet {
namespace {

constexpr std::pair<const char*, GpuFault> kFaults[] = {{"beauty-bias", GpuFault::BeautyBias},
                                                        {"dropped-tile", GpuFault::DroppedTile},
                                                        {"shifted-pixel", GpuFault::ShiftedPixel},
                                                        {"flipped-normal", GpuFault::FlippedNormal},
                                                        {"beauty-ulp", GpuFault::BeautyUlp}};

// Each row of `plane` one pixel to the right; the first column keeps what
// a missed pixel holds.
template <class T>
void shiftRight(std::vector<T>& plane, int width, const T& missed) {
  if (plane.empty()) return;
  for (std::size_t row = 0; row < plane.size(); row += std::size_t(width)) {
    std::move_backward(plane.begin() + std::ptrdiff_t(row), plane.begin() + std::ptrdiff_t(row + width - 1),
                       plane.begin() + std::ptrdiff_t(row + width));
    plane[row] = missed;
  }
}

}  // namespace

std::optional<GpuFault> gpuFaultFromEnvironment() {
  const char* named = std::getenv("FACET_FAULT");
  if (!named || !*named) return std::nullopt;
  for (const auto& [name, fault] : kFaults)
    if (std::string(named) == name) return fault;
  throw std::invalid_argument(std::string("FACET_FAULT '") + named + "': expected one of: " + kGpuFaultNames +
                              " (docs/parity.md, \"Proving the gate\")");
}

const char* toString(GpuFault fault) {
  for (const auto& [name, value] : kFaults)
    if (value == fault) return name;
  return "?";
}

void injectFault(GpuFault fault, Image& image) {
  switch (fault) {
    case GpuFault::BeautyBias:
      for (glm::vec4& b : image.beauty) b = glm::vec4(glm::vec3(b) * 1.01f, b.a);
      return;
    case GpuFault::BeautyUlp:
      for (glm::vec4& b : image.beauty)
        for (int c = 0; c < 3; ++c) b[c] = std::nextafter(b[c], INFINITY);
      return;
    case GpuFault::DroppedTile: {
      const int x0 = std::max(0, image.width / 2 - 8), y0 = std::max(0, image.height / 2 - 8);
      for (int y = y0; y < std::min(image.height, y0 + 16); ++y)
        for (int x = x0; x < std::min(image.width, x0 + 16); ++x) {
          glm::vec4& b = image.beauty[image.index(x, y)];
          b = glm::vec4(0, 0, 0, b.a);
        }
      return;
    }
    case GpuFault::ShiftedPixel:
      shiftRight(image.beauty, image.width, glm::vec4(0));
      shiftRight(image.depth, image.width, INFINITY);
      shiftRight(image.position, image.width, glm::vec3(0));
      shiftRight(image.geometricNormal, image.width, glm::vec3(0));
      shiftRight(image.shadingNormal, image.width, glm::vec3(0));
      shiftRight(image.patchId, image.width, Image::kNoId);
      shiftRight(image.faceId, image.width, Image::kNoId);
      shiftRight(image.uv, image.width, glm::vec2(0));
      shiftRight(image.texcoord, image.width, glm::vec2(0));
      return;
    case GpuFault::FlippedNormal: {
      // The covered pixel nearest the middle of the image.
      const std::size_t middle = image.index(image.width / 2, image.height / 2);
      for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const std::size_t p = (middle + i) % image.pixelCount();
        if (image.beauty[p].a < 1 || image.shadingNormal.empty()) continue;
        image.shadingNormal[p] = -image.shadingNormal[p];
        return;
      }
      return;
    }
  }
}

}  // namespace facet

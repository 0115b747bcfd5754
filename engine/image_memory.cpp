#include "engine/image_memory.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <stdexcept>

#include "scenes/memory_budget.h"

namespace facet {
namespace {

// Every plane of an Image; the GPU backend works in bands of bounded size
// and the CPU backend writes straight into the image, so the image dominates.
constexpr std::uint64_t kImageBytesPerPixel =
    sizeof(glm::vec4) + sizeof(float) + 3 * sizeof(glm::vec3) + 2 * sizeof(std::uint32_t) + sizeof(glm::vec2);
// What the PNG preview or the parity heat map adds per pixel, and a bound on
// the GPU backend's band buffers (kBandBytes in engine/gpu_backend/gpu_renderer.cpp).
constexpr std::uint64_t kWorkingBytesPerPixel = 8;
constexpr std::uint64_t kGpuBandBytes = std::uint64_t(64) << 20;

std::uint64_t bytesNeeded(const scene::Scene& scene, int images, const std::optional<PixelRect>& crop) {
  const std::uint64_t pixels =
      crop ? crop->pixelCount() : std::uint64_t(scene.render.width) * std::uint64_t(scene.render.height);
  return pixels * (std::uint64_t(images) * kImageBytesPerPixel + kWorkingBytesPerPixel) + kGpuBandBytes;
}

}  // namespace

bool imagesFitInMemory(const scene::Scene& scene, int images, const std::optional<PixelRect>& crop) {
  return bytesNeeded(scene, images, crop) <= scene::memoryLimit().bytes;
}

void checkImagesFitInMemory(const scene::Scene& scene, int images, const std::string& sizeSource,
                            const std::optional<PixelRect>& crop) {
  const std::uint64_t needed = bytesNeeded(scene, images, crop);
  const scene::MemoryLimit limit = scene::memoryLimit();
  if (needed > limit.bytes)
    throw std::invalid_argument(
        sizeSource + " " + std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height) +
        (crop ? ", crop " + crop->text() : "") + ": the render needs about " + scene::gigabytes(needed) +
        " of memory and the limit is " + scene::gigabytes(limit.bytes) + " (" + limit.source +
        "); give a smaller size" + (crop ? " or more --tile tiles" : " or render it as --tile tiles"));
}

}  // namespace facet

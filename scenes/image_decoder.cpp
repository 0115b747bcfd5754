#include "scenes/image_decoder.h"

// stb_image's PNG and JPEG decoders, static so that no stbi symbol leaves
// the binary for a shared library (tinygltf) to bind to; the HDR-only copy
// in environment_map.cpp is a separate, equally private one.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#include <stb_image.h>

#include <climits>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/memory_budget.h"

namespace facet::scene {

namespace {

// Channel values of `count` decoded samples of type T, divided by its range.
template <class T>
std::vector<float> normalized(const T* samples, std::size_t count, float range) {
  std::vector<float> channels(count);
  for (std::size_t i = 0; i < count; ++i) channels[i] = float(samples[i]) / range;
  return channels;
}

}  // namespace

DecodedImage decodeImage(const std::string& encoded, const std::string& source, int maxSize) {
  if (encoded.size() > std::size_t(INT_MAX))
    throw InputError(source, 0, "cannot decode the image", "an encoded image must be under 2 GiB");
  const auto* bytes = reinterpret_cast<const stbi_uc*>(encoded.data());
  const int length = int(encoded.size());
  DecodedImage image;
  if (!stbi_info_from_memory(bytes, length, &image.width, &image.height, &image.components))
    throw InputError(source, 0, "cannot decode the image (PNG or JPEG expected)", stbi_failure_reason());
  if (image.width > maxSize || image.height > maxSize)
    throw InputError(source, 0, "an image must be at most " + std::to_string(maxSize) + " x " + std::to_string(maxSize),
                     "it is " + std::to_string(image.width) + " x " + std::to_string(image.height));
  const bool wide = stbi_is_16_bit_from_memory(bytes, length);
  checkTextureFitsInMemory(source, "image", image.width, image.height, image.components, wide ? 2 : 1);
  const std::size_t count = std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.components);
  int w = 0, h = 0, n = 0;
  if (wide) {
    const std::unique_ptr<stbi_us, void (*)(void*)> samples(stbi_load_16_from_memory(bytes, length, &w, &h, &n, 0),
                                                            stbi_image_free);
    if (samples) image.channels = normalized(samples.get(), count, 65535.0f);
  } else {
    const std::unique_ptr<stbi_uc, void (*)(void*)> samples(stbi_load_from_memory(bytes, length, &w, &h, &n, 0),
                                                            stbi_image_free);
    if (samples) image.channels = normalized(samples.get(), count, 255.0f);
  }
  if (image.channels.empty()) throw InputError(source, 0, "cannot decode the image", stbi_failure_reason());
  return image;
}

DecodedImage decodeImage(const std::filesystem::path& file, int maxSize) {
  checkInputFile(file, "the image");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "cannot open the image", "the file cannot be read");
  return decodeImage(std::string(std::istreambuf_iterator<char>(in), {}), file.string(), maxSize);
}

}  // namespace facet::scene

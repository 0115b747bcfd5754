#include "scenes/image_decoder.h"

// stb_image's PNG and JPEG decoders, static so that no stbi symbol leaves
// the binary for a shared library (tinygltf) to bind to; the HDR-only copy
// in environment_map.cpp is a separate, equally private one.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#include <stb_image.h>

#include <cstdint>
#include <memory>
#include <string>

#include "scenes/input_error.h"
#include "scenes/input_file.h"

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

DecodedImage decodeImage(const std::filesystem::path& file, int maxSize) {
  const std::string source = file.string();
  checkInputFile(file, "the image");
  DecodedImage image;
  if (!stbi_info(source.c_str(), &image.width, &image.height, &image.components))
    throw InputError(source, 0, "cannot decode the image (PNG or JPEG expected)", stbi_failure_reason());
  if (image.width > maxSize || image.height > maxSize)
    throw InputError(source, 0, "an image must be at most " + std::to_string(maxSize) + " x " + std::to_string(maxSize),
                     "it is " + std::to_string(image.width) + " x " + std::to_string(image.height));
  const std::size_t count = std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.components);
  int w = 0, h = 0, n = 0;
  if (stbi_is_16_bit(source.c_str())) {
    const std::unique_ptr<stbi_us, void (*)(void*)> samples(stbi_load_16(source.c_str(), &w, &h, &n, 0),
                                                            stbi_image_free);
    if (samples) image.channels = normalized(samples.get(), count, 65535.0f);
  } else {
    const std::unique_ptr<stbi_uc, void (*)(void*)> samples(stbi_load(source.c_str(), &w, &h, &n, 0), stbi_image_free);
    if (samples) image.channels = normalized(samples.get(), count, 255.0f);
  }
  if (image.channels.empty()) throw InputError(source, 0, "cannot decode the image", stbi_failure_reason());
  return image;
}

}  // namespace facet::scene

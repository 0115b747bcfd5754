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
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/memory_budget.h"

namespace facet::scene {

DecodedSamples decodeSamples(std::span<const unsigned char> encoded, const std::string& source,
                             const std::string& field, int maxSize, std::uint64_t heldBytes) {
  if (encoded.size() > std::size_t(INT_MAX))
    throw InputError(source, 0, field, "cannot decode the image: an encoded image must be under 2 GiB");
  const auto* bytes = reinterpret_cast<const stbi_uc*>(encoded.data());
  const int length = int(encoded.size());
  DecodedSamples image;
  if (!stbi_info_from_memory(bytes, length, &image.width, &image.height, &image.components))
    throw InputError(source, 0, field,
                     std::string("cannot decode the image (PNG or JPEG expected): ") + stbi_failure_reason());
  if (image.width > maxSize || image.height > maxSize)
    throw InputError(source, 0, field,
                     "an image must be at most " + std::to_string(maxSize) + " x " + std::to_string(maxSize) +
                         ", it is " + std::to_string(image.width) + " x " + std::to_string(image.height));
  image.bytesPerSample = stbi_is_16_bit_from_memory(bytes, length) ? 2 : 1;
  checkTextureFitsInMemory(source, field, image.width, image.height, image.components, image.bytesPerSample, heldBytes);
  int w = 0, h = 0, n = 0;
  void* samples = image.bytesPerSample == 2 ? static_cast<void*>(stbi_load_16_from_memory(bytes, length, &w, &h, &n, 0))
                                            : static_cast<void*>(stbi_load_from_memory(bytes, length, &w, &h, &n, 0));
  image.samples = {static_cast<unsigned char*>(samples), stbi_image_free};
  if (!samples) throw InputError(source, 0, field, std::string("cannot decode the image: ") + stbi_failure_reason());
  // The buffer is as the decoder made it, which the header only predicts.
  image.width = w;
  image.height = h;
  image.components = n;
  return image;
}

DecodedImage decodeImage(const std::filesystem::path& file, int maxSize) {
  checkInputFile(file, "the image");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "cannot open the image", "the file cannot be read");
  const std::vector<unsigned char> encoded{std::istreambuf_iterator<char>(in), {}};
  const DecodedSamples samples = decodeSamples(encoded, file.string(), "image", maxSize);
  DecodedImage image{samples.width, samples.height, samples.components, {}};
  const std::size_t count = samples.byteCount() / std::size_t(samples.bytesPerSample);
  image.channels.resize(count);
  const unsigned char* data = samples.samples.get();
  for (std::size_t i = 0; i < count; ++i) {
    std::uint16_t wide = 0;
    if (samples.bytesPerSample == 2) std::memcpy(&wide, data + 2 * i, 2);
    image.channels[i] = samples.bytesPerSample == 2 ? float(wide) / 65535.0f : float(data[i]) / 255.0f;
  }
  return image;
}

}  // namespace facet::scene

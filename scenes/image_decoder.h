// PNG and JPEG images decoded to channel values in [0, 1], as stored (no
// transfer function applied): what texture files named by a scene hold.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace facet::scene {

struct DecodedImage {
  int width = 0;
  int height = 0;
  int components = 0;           // 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA
  std::vector<float> channels;  // row-major from the first row, `components` per texel
};

// An image's samples as the file stores them, 8 or 16 bits each (16-bit
// samples in the machine's byte order), row-major from the first row.
struct DecodedSamples {
  int width = 0;
  int height = 0;
  int components = 0;
  int bytesPerSample = 1;
  std::unique_ptr<unsigned char, void (*)(void*)> samples{nullptr, nullptr};

  std::size_t byteCount() const {
    return std::size_t(width) * std::size_t(height) * std::size_t(components) * std::size_t(bytesPerSample);
  }
};

// Reads 8- and 16-bit PNG and baseline or progressive JPEG. Throws
// InputError naming `source` and `field` when the bytes cannot be decoded,
// the image is larger than `maxSize` texels on a side, or its texture would
// not fit in memory beside the `heldBytes` earlier images keep
// (scenes/memory_budget.h): the last two are checked from the image's
// header, before any texel is decoded.
DecodedSamples decodeSamples(std::span<const unsigned char> encoded, const std::string& source,
                             const std::string& field, int maxSize, std::uint64_t heldBytes = 0);

// The image file `file` (a regular file, scenes/input_file.h), decoded as
// decodeSamples decodes, with its channels normalized.
DecodedImage decodeImage(const std::filesystem::path& file, int maxSize);

}  // namespace facet::scene

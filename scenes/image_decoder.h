// PNG and JPEG images decoded to channel values in [0, 1], as stored (no
// transfer function applied): what texture files named by a scene hold.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace facet::scene {

struct DecodedImage {
  int width = 0;
  int height = 0;
  int components = 0;           // 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA
  std::vector<float> channels;  // row-major from the first row, `components` per texel
};

// Reads 8- and 16-bit PNG and baseline or progressive JPEG. Throws
// InputError naming the file (or `source`) when it cannot be read or
// decoded, is larger than `maxSize` texels on a side, or its texture would
// not fit in memory (scenes/memory_budget.h): the last two are checked from
// the image's header, before any texel is decoded.
DecodedImage decodeImage(const std::filesystem::path& file, int maxSize);
DecodedImage decodeImage(const std::string& encoded, const std::string& source, int maxSize);

}  // namespace facet::scene

// The colour-space chunks of a PNG, which stb_image_write does not write
// (PNG specification, 3rd edition, 11.3.2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet {

// The CRC-32 of a chunk's type and data (PNG specification, Annex D).
std::uint32_t pngCrc(const std::uint8_t* bytes, std::size_t count);

// `png` (a whole file, its IHDR first as the format requires) with sRGB
// (perceptual intent), and the gAMA and cHRM values the specification
// gives for decoders that do not read sRGB, inserted after IHDR.
std::vector<std::uint8_t> withSrgbChunks(const std::uint8_t* png, std::size_t size);

}  // namespace facet

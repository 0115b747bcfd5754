#include "engine/image/png_chunks.h"

#include <stdexcept>
#include <string_view>

namespace facet {
namespace {

constexpr std::size_t kSignatureBytes = 8;
constexpr std::size_t kIhdrChunkBytes = 4 + 4 + 13 + 4;  // length, type, data, CRC

void appendBigEndian(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(value >> shift));
}

void appendChunk(std::vector<std::uint8_t>& out, std::string_view type, const std::vector<std::uint32_t>& words,
                 std::size_t dataBytes) {
  appendBigEndian(out, std::uint32_t(dataBytes));
  const std::size_t typeStart = out.size();
  out.insert(out.end(), type.begin(), type.end());
  if (dataBytes == 1)
    out.push_back(std::uint8_t(words.front()));
  else
    for (std::uint32_t word : words) appendBigEndian(out, word);
  appendBigEndian(out, pngCrc(out.data() + typeStart, out.size() - typeStart));
}

}  // namespace

std::uint32_t pngCrc(const std::uint8_t* bytes, std::size_t count) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < count; ++i) {
    crc ^= bytes[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

std::vector<std::uint8_t> withSrgbChunks(const std::uint8_t* png, std::size_t size) {
  const std::size_t afterIhdr = kSignatureBytes + kIhdrChunkBytes;
  if (size < afterIhdr || std::string_view(reinterpret_cast<const char*>(png) + 12, 4) != "IHDR")
    throw std::invalid_argument("not a PNG that starts with its IHDR chunk");
  std::vector<std::uint8_t> out(png, png + afterIhdr);
  appendChunk(out, "sRGB", {0}, 1);  // rendering intent 0: perceptual
  appendChunk(out, "gAMA", {45455}, 4);
  appendChunk(out, "cHRM", {31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000}, 32);  // white, red, green, blue
  out.insert(out.end(), png + afterIhdr, png + size);
  return out;
}

}  // namespace facet

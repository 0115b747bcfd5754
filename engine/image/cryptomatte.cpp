#include "engine/image/cryptomatte.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdio>

namespace facet {
namespace {

std::uint32_t rotateLeft(std::uint32_t x, int r) { return (x << r) | (x >> (32 - r)); }

}  // namespace

std::uint32_t murmurHash3(std::string_view text, std::uint32_t seed) {
  constexpr std::uint32_t c1 = 0xcc9e2d51u, c2 = 0x1b873593u;
  const auto byte = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(text[i])); };
  const auto scramble = [&](std::uint32_t k) { return rotateLeft(k * c1, 15) * c2; };
  std::uint32_t h = seed;
  const std::size_t blocks = text.size() / 4;
  for (std::size_t b = 0; b < blocks; ++b) {  // little-endian 4-byte blocks
    const std::size_t i = 4 * b;
    h ^= scramble(byte(i) | byte(i + 1) << 8 | byte(i + 2) << 16 | byte(i + 3) << 24);
    h = rotateLeft(h, 13) * 5 + 0xe6546b64u;
  }
  std::uint32_t tail = 0;
  for (std::size_t i = text.size(); i-- > 4 * blocks;) tail = tail << 8 | byte(i);
  if (text.size() % 4 != 0) h ^= scramble(tail);
  h ^= std::uint32_t(text.size());
  h ^= h >> 16;  // finalisation mix
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

float cryptomatteId(std::string_view name) {
  const std::uint32_t hash = murmurHash3(name);
  const std::uint32_t exponent = std::clamp((hash >> 23) & 0xffu, 1u, 254u);
  return std::bit_cast<float>((hash & 0x807fffffu) | exponent << 23);
}

std::string cryptomatteHex(float id) {
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", std::bit_cast<std::uint32_t>(id));
  return hex;
}

std::string cryptomatteKey(std::string_view layer) {
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", murmurHash3(layer));
  return std::string(hex, 7);
}

std::string cryptomatteManifest(const std::vector<std::string>& names) {
  nlohmann::json manifest = nlohmann::json::object();
  for (const std::string& name : names) manifest[name] = cryptomatteHex(cryptomatteId(name));
  return manifest.dump();
}

}  // namespace facet

// Cryptomatte ID layers (Friedman & Jones, "Fully Automatic ID Mattes with
// Support for Motion Blur and Transparency", and the Cryptomatte
// specification 1.1.0): names hashed to floats, a manifest from names to
// hashes, and the header key of a layer.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

// MurmurHash3_x86_32 (Appleby, SMHasher) of the bytes of `text`.
std::uint32_t murmurHash3(std::string_view text, std::uint32_t seed = 0);

// The spec's uint32_to_float32: the hash's bits as a float with the exponent
// clamped to [1, 254], so that an id is never zero, denormal, Inf or NaN.
float cryptomatteId(std::string_view name);

// The 8 hex digits of an id's float bits, as the manifest writes them.
std::string cryptomatteHex(float id);

// The header key of a layer: the first 7 hex digits of its name's hash.
std::string cryptomatteKey(std::string_view layer);

// {"name":"hex", ...}, each distinct name once, in JSON.
std::string cryptomatteManifest(const std::vector<std::string>& names);

}  // namespace facet

// The bytes of a prefilter-cache file (engine/ibl/prefilter_cache.cpp keeps
// them on disk): a head (a magic, the format's version, the key's text), the
// payload, and a tail (an FNV-1a checksum of every byte before it, and the
// magic again). The key's text makes a hash collision read as nothing, the
// checksum a changed byte, the tail a truncated file; a payload must parse
// to its last byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/ibl/prefiltered_environment.h"

namespace facet::ibl::cache_format {

// Bump whenever the layout changes. What the builders compute is keyed by
// FACET_PREFILTER_FINGERPRINT, a digest of their sources that
// engine/ibl/CMakeLists.txt takes at configure time.
constexpr std::uint32_t kFormatVersion = 3;

// FNV-1a, 64-bit; a running hash continues from `hash`, so that a file
// read in pieces hashes as it would whole.
inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;
std::uint64_t fnv1a(const char* bytes, std::size_t size, std::uint64_t hash = kFnv1aOffsetBasis);

// A file holding `payload` under `key`.
std::vector<char> seal(const std::string& key, const std::vector<char>& payload);
// The payload of `file` when its head names `key` and its tail holds.
std::optional<std::vector<char>> unseal(const std::vector<char>& file, const std::string& key);

std::vector<char> environmentPayload(const PrefilteredEnvironment& env);
std::optional<PrefilteredEnvironment> environmentFromPayload(const std::vector<char>& payload);
std::vector<char> tablePayload(const DfgTable& table);
std::optional<DfgTable> tableFromPayload(const std::vector<char>& payload);

// Whether what a file held fits the request, as the renderers index it
// without a check: the table's pair and size, or the levels the prefilter
// gives `map` (its size, then each ladder level's size and roughness,
// prefilter_steps.h), the irradiance map's size and a table per model pair
// in request order; finite values everywhere.
bool tableFits(const DfgTable& table, int distribution, int geometry, const PrefilterSettings& settings);
bool environmentFits(const PrefilteredEnvironment& env, const scene::EnvironmentMap& map, const ModelPairs& models,
                     const PrefilterSettings& settings);

}  // namespace facet::ibl::cache_format

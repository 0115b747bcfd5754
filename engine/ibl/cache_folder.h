// facet's cache folder: what is worth keeping between processes (the
// prefiltered environments, the DFG tables, the device's pipeline cache),
// one file per key, each written whole or not at all. Any failure to read or
// write only costs a rebuild.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace facet::ibl {

// FACET_CACHE_DIR, else $XDG_CACHE_HOME/facet, else ~/.cache/facet; none
// where none of these is set.
std::optional<std::filesystem::path> cacheDirectory();

// The file of `key` in `directory`: `<prefix>-<FNV-1a of the key, hex>.bin`.
// The key's whole text goes into the file's head (prefilter_cache_format.h),
// so two keys of one hash read as a miss.
std::filesystem::path cacheFile(const std::filesystem::path& directory, const std::string& prefix,
                                const std::string& key);

// A regular file's bytes; none for a missing, special or oversized file (a
// FIFO would block the read, a device never end it) or a failed read.
std::optional<std::vector<char>> readCacheFile(const std::filesystem::path& file);

// To a temporary file of this writer's own, renamed over `file`, so that a
// reader sees the old file or the new one, never a part; the folder is made
// where missing. Failures are silent: the cache is an optimization.
void writeCacheFileAtomically(const std::filesystem::path& file, const std::vector<char>& data);

}  // namespace facet::ibl

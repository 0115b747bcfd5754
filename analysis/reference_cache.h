// The CPU reference's renders of a parity run, kept in facet's cache folder
// (engine/ibl/cache_folder.h) between processes, so that judging a new
// driver on the same scenes costs the GPU's renders alone (docs/parity.md,
// "The reference cache"). A file is sealed as the prefilter cache's are:
// its key's text in its head, a checksum and a tail, so a collision, a
// changed byte or a cut file reads as nothing. The folder's reference files
// are held under a budget (kReferenceCacheBytes), those least recently used
// removed first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "scenes/scene.h"

namespace facet::analysis {

inline constexpr std::uintmax_t kReferenceCacheBytes = std::uintmax_t(1) << 30;

// What a parity run keeps of its reference: the first render with every
// AOV, each later render's beauty alone (all the paired test reads of it).
struct CachedReference {
  std::string device;  // what rendered them
  Image first;
  std::vector<std::vector<glm::vec4>> laterBeauty;

  int renders() const { return first.width > 0 ? 1 + int(laterBeauty.size()) : 0; }
  // Render `i` as PairedRenders takes it: the first whole, a later one its beauty.
  Image render(int i) const;
  void add(const Image& render);
};

// Records the shared libraries the running program has mapped: a program
// that caches references calls it first thing in main, before any Vulkan
// driver is loaded, so that an upgrade renders anew and a new driver does
// not. (The program's own bytes, which make a rebuild render anew, are
// hashed when a key first needs them.)
void recordProgramAtStart();

// What decides `scene`'s reference renders, but for how many there are: the
// program recordProgramAtStart recorded, the contents of every file the
// scene was read from (`inputs`, scenes/input_file.h's log), `shapedBy`
// (what else made the scene what it is: the command line's edits and
// overrides), the settings the scene renders with and its first seed. Empty
// where the program was not recorded (the APIs) or it or an input cannot be
// read: then nothing is cached.
std::string referenceKey(const scene::Scene& scene, const std::vector<std::filesystem::path>& inputs,
                         const std::string& shapedBy);

// `key` (referenceKey's) for a run of `renders` renders; empty for an empty key.
std::string rendersKey(const std::string& key, int renders);

// The bytes `renders` renders of width x height take in a cache file.
std::uintmax_t referenceBytes(int width, int height, int renders);

// A cache file's payload, and the renders it holds when it holds `renders`
// of them at `width` x `height` to its last byte.
std::vector<char> referencePayload(const CachedReference& reference);
std::optional<CachedReference> referenceFromPayload(const std::vector<char>& payload, int width, int height,
                                                    int renders);

// The renders stored under `key` when a file holds them intact, `renders`
// of them at the scene's size.
std::optional<CachedReference> loadReference(const std::string& key, int width, int height, int renders);

// Stored under `key`, then the oldest reference files removed until the
// folder's fit `budget` bytes; failures are silent, as the cache is an
// optimization.
void storeReference(const std::string& key, const CachedReference& reference,
                    std::uintmax_t budget = kReferenceCacheBytes);

}  // namespace facet::analysis

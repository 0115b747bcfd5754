// How much memory one facet process lets itself use, and the estimates it
// holds inputs to before allocating for them (docs/reliability.md, "Limits").
// The CLI and both APIs apply the same limit, so a render one of them
// refuses is refused by all; engine/image_memory.h checks a render's images.
#pragma once

#include <cstdint>
#include <string>

namespace facet::scene {

struct MemoryLimit {
  std::uint64_t bytes;
  std::string source;  // where the limit comes from, for the error message
};

// FACET_MEMORY_LIMIT (a whole number of MiB) when set; otherwise three
// quarters of the memory this process may use: physical memory, or the
// cgroup's memory.max or the address-space limit (ulimit -v) when lower.
// The other quarter is the system's, the driver's and the scene's.
MemoryLimit memoryLimit();

// "1.2 GB": bytes for a message.
std::string gigabytes(std::uint64_t bytes);

// A bound on the memory of turning a width x height image of `components`
// channels of `bytesPerSample` bytes into a texture: the decoder's samples,
// their float copy, and the RGBA float levels (4/3 of level 0), together.
std::uint64_t textureBuildBytes(int width, int height, int components, int bytesPerSample);

// What a built texture and its decoded samples keep once the build is done:
// the samples, and the RGBA float levels.
std::uint64_t textureHeldBytes(int width, int height, int components, int bytesPerSample);

// Throws InputError naming `source` and `field` when textureBuildBytes, with
// the `heldBytes` that earlier images of the same file keep, exceeds
// memoryLimit(): checked from the image's header, before decoding.
void checkTextureFitsInMemory(const std::string& source, const std::string& field, int width, int height,
                              int components, int bytesPerSample, std::uint64_t heldBytes = 0);

}  // namespace facet::scene

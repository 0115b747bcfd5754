// The device's pipeline cache (gpu::Device::pipelineCacheData) kept on disk
// in facet's cache folder (engine/ibl/cache_folder.h), so that a driver that
// fills it compiles no pipeline a render compiled before. One file per
// facet version, kernels and driver build, sealed as the prefilter cache's
// files are (engine/ibl/prefilter_cache_format.h: the key's text, an FNV-1a
// checksum, the magic at both ends); docs/reliability.md, "Caches".
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"

namespace facet::gpu_backend {

// The file of `adapter`'s pipeline cache; none without a cache folder.
std::optional<std::filesystem::path> pipelineCacheFile(const gpu::AdapterInfo& adapter);

struct StoredPipelineCache {
  std::vector<std::byte> data;  // for gpu::DeviceDescriptor::pipelineCache; empty: start empty
  // Why a file that is there was not used (damaged, another facet's or
  // another driver's), in the words of a warning; empty otherwise.
  std::string warning;
};

// What `adapter`'s file holds when it is intact, facet's and this driver's
// (its Vulkan header names this adapter); anything else is never handed to
// the driver.
StoredPipelineCache loadPipelineCache(const gpu::AdapterInfo& adapter);

// `device`'s pipeline cache, written over its file whole.
void storePipelineCache(const gpu::Device& device);

}  // namespace facet::gpu_backend

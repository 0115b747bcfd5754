#include "engine/gpu_backend/pipeline_cache_file.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <tuple>

#include "engine/ibl/cache_folder.h"
#include "engine/ibl/prefilter_cache_format.h"
#include "facet/version.h"
#include "facet_raycast_kernels/spirv.h"

namespace facet::gpu_backend {

namespace {

namespace fs = std::filesystem;

// Drivers key their entries by the shader, so a changed kernel only adds
// one; keying the file by the kernels too keeps stale entries from piling up.
std::uint64_t kernelsDigest() {
  const std::span<const std::uint32_t> kernels[] = {
      raycast::spirv::dice_grid,        raycast::spirv::dice_cells, raycast::spirv::build_quadtrees,
      raycast::spirv::refit_top_levels, raycast::spirv::intersect,  raycast::spirv::surface,
      raycast::spirv::dispatch_args,    raycast::spirv::fallback,   raycast::spirv::fallback_resolve,
      raycast::spirv::shadow,           raycast::spirv::gather,     raycast::spirv::resolve,
      raycast::spirv::continue_paths};
  std::uint64_t digest = 0;
  for (std::span<const std::uint32_t> code : kernels)
    digest = digest * 31 + ibl::cache_format::fnv1a(reinterpret_cast<const char*>(code.data()), code.size_bytes());
  return digest;
}

std::string keyText(const gpu::AdapterInfo& adapter) {
  char uuid[33];
  for (std::size_t i = 0; i < adapter.pipelineCacheUuid.size(); ++i)
    std::snprintf(uuid + 2 * i, 3, "%02x", adapter.pipelineCacheUuid[i]);
  char key[256];
  std::snprintf(key, sizeof key,
                "facet pipeline cache v1 facet %s kernels %016llx vendor %08x device %08x driver %08x uuid %s",
                FACET_VERSION_STRING, static_cast<unsigned long long>(kernelsDigest()), adapter.vendorId,
                adapter.deviceId, adapter.driverVersion, uuid);
  return key;
}

// Vulkan's VkPipelineCacheHeaderVersionOne, read field by field.
bool headerNames(const std::vector<char>& data, const gpu::AdapterInfo& adapter) {
  constexpr std::size_t kUuidBytes = std::tuple_size_v<decltype(adapter.pipelineCacheUuid)>;
  constexpr std::size_t kHeaderBytes = 16 + kUuidBytes;
  if (data.size() < kHeaderBytes) return false;
  std::uint32_t fields[4];
  std::memcpy(fields, data.data(), sizeof fields);
  return fields[0] >= kHeaderBytes && fields[0] <= data.size() && fields[1] == 1 /* version one */ &&
         fields[2] == adapter.vendorId && fields[3] == adapter.deviceId &&
         std::memcmp(data.data() + 16, adapter.pipelineCacheUuid.data(), kUuidBytes) == 0;
}

}  // namespace

std::optional<fs::path> pipelineCacheFile(const gpu::AdapterInfo& adapter) {
  const std::optional<fs::path> directory = ibl::cacheDirectory();
  if (!directory) return std::nullopt;
  return ibl::cacheFile(*directory, "pipelines", keyText(adapter));
}

StoredPipelineCache loadPipelineCache(const gpu::AdapterInfo& adapter) {
  const std::optional<fs::path> file = pipelineCacheFile(adapter);
  if (!file) return {};
  const std::optional<std::vector<char>> bytes = ibl::readCacheFile(*file);
  if (!bytes) return {};
  const std::optional<std::vector<char>> payload = ibl::cache_format::unseal(*bytes, keyText(adapter));
  if (!payload || !headerNames(*payload, adapter))
    return {{},
            "pipeline cache " + file->string() +
                ": damaged, or not this facet's and this driver's; ignored, and written again after this render"};
  const auto* begin = reinterpret_cast<const std::byte*>(payload->data());
  return {{begin, begin + payload->size()}, {}};
}

void storePipelineCache(const gpu::Device& device) {
  const std::optional<fs::path> file = pipelineCacheFile(device.adapterInfo());
  if (!file) return;
  const std::vector<std::byte> data = device.pipelineCacheData();
  const auto* begin = reinterpret_cast<const char*>(data.data());
  ibl::writeCacheFileAtomically(*file,
                                ibl::cache_format::seal(keyText(device.adapterInfo()), {begin, begin + data.size()}));
}

}  // namespace facet::gpu_backend

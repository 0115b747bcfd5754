#include "scenes/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "scenes/input_error.h"

namespace facet::scene {
namespace {

// 0 when the cgroup sets no limit ("max") or there is no cgroup v2.
std::uint64_t cgroupMemoryLimit() {
  std::uint64_t limit = 0;
  if (std::FILE* file = std::fopen("/sys/fs/cgroup/memory.max", "r")) {
    if (std::fscanf(file, "%" SCNu64, &limit) != 1) limit = 0;
    std::fclose(file);
  }
  return limit;
}

}  // namespace

MemoryLimit memoryLimit() {
  if (const char* text = std::getenv("FACET_MEMORY_LIMIT")) {
    char* end = nullptr;
    const unsigned long long mebibytes = std::strtoull(text, &end, 10);
    if (end == text || *end != 0 || mebibytes == 0 || mebibytes > (std::uint64_t(1) << 40))
      throw std::invalid_argument(std::string("FACET_MEMORY_LIMIT '") + text + "': expected a whole number of MiB");
    return {std::uint64_t(mebibytes) << 20, "FACET_MEMORY_LIMIT"};
  }
  std::uint64_t memory = std::uint64_t(sysconf(_SC_PHYS_PAGES)) * std::uint64_t(sysconf(_SC_PAGE_SIZE));
  const char* source = "3/4 of this machine's memory";
  if (const std::uint64_t cgroup = cgroupMemoryLimit(); cgroup > 0 && cgroup < memory) {
    memory = cgroup;
    source = "3/4 of the cgroup's memory.max";
  }
  if (rlimit space{};
      getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY && std::uint64_t(space.rlim_cur) < memory) {
    memory = std::uint64_t(space.rlim_cur);
    source = "3/4 of the address-space limit (ulimit -v)";
  }
  return {memory / 4 * 3, source};
}

std::string gigabytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", double(bytes) * 1e-9);
  return text;
}

std::uint64_t textureBuildBytes(int width, int height, int components, int bytesPerSample) {
  const std::uint64_t samples = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(components);
  return textureHeldBytes(width, height, components, bytesPerSample) + samples * sizeof(float);
}

std::uint64_t textureHeldBytes(int width, int height, int components, int bytesPerSample) {
  const std::uint64_t texels = std::uint64_t(width) * std::uint64_t(height);
  const std::uint64_t levels = texels * 4 * sizeof(float) * 4 / 3;
  return texels * std::uint64_t(components) * std::uint64_t(bytesPerSample) + levels;
}

void checkTextureFitsInMemory(const std::string& source, const std::string& field, int width, int height,
                              int components, int bytesPerSample, std::uint64_t heldBytes) {
  const std::uint64_t needed = textureBuildBytes(width, height, components, bytesPerSample);
  const MemoryLimit limit = memoryLimit();
  if (needed + heldBytes > limit.bytes)
    throw InputError(source, 0, field,
                     "a " + std::to_string(width) + " x " + std::to_string(height) + " texture needs about " +
                         gigabytes(needed) + " of memory to build" +
                         (heldBytes > 0 ? ", the images before it keep " + gigabytes(heldBytes) + "," : "") +
                         " and the limit is " + gigabytes(limit.bytes) + " (" + limit.source + "); scale the image" +
                         (heldBytes > 0 ? "s" : "") + " down");
}

}  // namespace facet::scene

#include "engine/ibl/cache_folder.h"

#include "engine/ibl/prefilter_cache_format.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <system_error>

namespace facet::ibl {

namespace fs = std::filesystem;

namespace {

// A cache file larger than this is not one facet wrote (a link to a device).
constexpr std::uintmax_t kLargestFile = std::uintmax_t(4) << 30;

}  // namespace

fs::path cacheFile(const fs::path& directory, const std::string& prefix, const std::string& key) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(cache_format::fnv1a(key.data(), key.size())));
  return directory / (prefix + "-" + hash + ".bin");
}

std::optional<fs::path> cacheDirectory() {
  if (const char* dir = std::getenv("FACET_CACHE_DIR"); dir && *dir) return fs::path(dir);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "facet";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "facet";
  return std::nullopt;
}

std::optional<std::vector<char>> readCacheFile(const fs::path& file) {
  std::error_code error;
  if (!fs::is_regular_file(file, error) || fs::file_size(file, error) > kLargestFile || error) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return data;
}

void writeCacheFileAtomically(const fs::path& file, const std::vector<char>& data) {
  std::error_code error;
  fs::create_directories(file.parent_path(), error);
  // A name of its own per writer, so that concurrent renders never write
  // into one temporary file; rename then replaces the file whole.
  const fs::path temporary =
      file.string() + ".tmp" + std::to_string(std::random_device{}()) + std::to_string(std::random_device{}());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(data.data(), std::streamsize(data.size()));
    out.close();
    if (!out) {
      fs::remove(temporary, error);
      return;
    }
  }
  fs::rename(temporary, file, error);
  if (error) fs::remove(temporary, error);
}

}  // namespace facet::ibl

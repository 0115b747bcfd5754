// The disk cache of prefiltered environments and of DFG tables: one file
// per key, in the format of prefilter_cache_format.h. What a file holds must
// also fit the request (its levels, its tables, finite values) or it is
// rebuilt. Only regular files are read. Any failure to read or write only
// costs the build.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "engine/ibl/prefilter_cache_format.h"
#include "engine/ibl/prefiltered_environment.h"

namespace facet::ibl {

namespace {

namespace fs = std::filesystem;

using cache_format::fnv1a;
using cache_format::kFormatVersion;

// A cache file larger than this is not one facet wrote (a link to a device).
constexpr std::uintmax_t kLargestFile = std::uintmax_t(4) << 30;

std::uint64_t fnv1a(const std::string& text) { return fnv1a(text.data(), text.size()); }

std::string keyText(const scene::EnvironmentMap& map, const ModelPairs& models, const PrefilterSettings& settings,
                    const std::string& builder) {
  std::ostringstream key;
  key << "facet prefiltered environment v" << kFormatVersion << " code " << FACET_PREFILTER_FINGERPRINT << " map "
      << std::hex << map.contentHash() << std::dec << " levels " << settings.levels << " firstLevelWidth "
      << settings.firstLevelWidth << " samples " << settings.samples << " dfgSize " << settings.dfgSize
      << " dfgSamples " << settings.dfgSamples << " irradianceWidth " << settings.irradianceWidth << " models";
  for (const auto& [distribution, geometry] : models) key << " " << distribution << "/" << geometry;
  key << " builder " << builder;
  return key.str();
}

std::string dfgKeyText(int distribution, int geometry, const PrefilterSettings& settings) {
  std::ostringstream key;
  key << "facet dfg table v" << kFormatVersion << " code " << FACET_PREFILTER_FINGERPRINT << " dfgSize "
      << settings.dfgSize << " dfgSamples " << settings.dfgSamples << " model " << distribution << "/" << geometry;
  return key.str();
}

std::optional<fs::path> cacheDirectory() {
  if (const char* dir = std::getenv("FACET_CACHE_DIR"); dir && *dir) return fs::path(dir);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "facet";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "facet";
  return std::nullopt;
}

std::optional<std::vector<char>> readFile(const fs::path& file) {
  // A FIFO would block the read and a device never end it.
  std::error_code error;
  if (!fs::is_regular_file(file, error) || fs::file_size(file, error) > kLargestFile || error) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return data;
}

void writeFileAtomically(const fs::path& file, const std::vector<char>& data) {
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

// The stored value of `key` (file `<prefix>-<hash>.bin`) when present,
// intact and fitting the request, else `build`'s, stored.
template <class T, class ToPayload, class FromPayload, class Fits, class Build>
T cached(const std::string& prefix, const std::string& key, ToPayload toPayload, FromPayload fromPayload, Fits fits,
         Build build) {
  const std::optional<fs::path> directory = cacheDirectory();
  if (!directory) return build();
  char name[48];
  std::snprintf(name, sizeof name, "%s-%016llx.bin", prefix.c_str(), static_cast<unsigned long long>(fnv1a(key)));
  const fs::path file = *directory / name;
  try {
    if (const auto data = readFile(file))
      if (const auto payload = cache_format::unseal(*data, key))
        if (std::optional<T> stored = fromPayload(*payload); stored && fits(*stored)) return std::move(*stored);
  } catch (const std::exception&) {  // a file too large to hold: a miss like any other bad file
  }
  T value = build();
  writeFileAtomically(file, cache_format::seal(key, toPayload(value)));
  return value;
}

}  // namespace

PrefilteredEnvironment cachedPrefilter(const scene::EnvironmentMap& map, const ModelPairs& models,
                                       const PrefilterSettings& settings, const std::string& builder,
                                       const std::function<PrefilteredEnvironment()>& build) {
  return cached<PrefilteredEnvironment>(
      "prefiltered", keyText(map, models, settings, builder), cache_format::environmentPayload,
      cache_format::environmentFromPayload,
      [&](const PrefilteredEnvironment& env) { return cache_format::environmentFits(env, models, settings); }, build);
}

DfgTable cachedDfgTable(int distribution, int geometry, const PrefilterSettings& settings) {
  return cached<DfgTable>(
      "dfg", dfgKeyText(distribution, geometry, settings), cache_format::tablePayload, cache_format::tableFromPayload,
      [&](const DfgTable& table) { return cache_format::tableFits(table, distribution, geometry, settings); },
      [&] { return dfgTable(distribution, geometry, settings); });
}

}  // namespace facet::ibl

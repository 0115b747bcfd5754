// The disk cache of prefiltered environments and of DFG tables. One file
// per key; the file repeats the key's text, so that a hash collision reads
// as a miss, carries a checksum of everything before it, so that a changed
// byte does too, and ends in a magic, so that a truncated file does too. What
// a file holds must also fit the request (its levels, its tables, finite
// values) or it is rebuilt. Only regular files are read. Any failure to read
// or write only costs the build.
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "engine/ibl/prefiltered_environment.h"

namespace facet::ibl {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'F', 'A', 'C', 'E', 'T', 'I', 'B', 'L'};
// Bump whenever the file layout changes. What the builders compute is
// keyed by FACET_PREFILTER_FINGERPRINT, a digest of their sources that
// engine/ibl/CMakeLists.txt takes at configure time.
constexpr std::uint32_t kFormatVersion = 3;
// A cache file larger than this is not one facet wrote (a link to a device).
constexpr std::uintmax_t kLargestFile = std::uintmax_t(4) << 30;

std::uint64_t fnv1a(const char* bytes, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

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

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const auto* bytes = reinterpret_cast<const char*>(&value);
    data_.insert(data_.end(), bytes, bytes + sizeof(T));
  }
  template <class T>
  void putArray(const std::vector<T>& values) {
    put(std::uint64_t(values.size()));
    const auto* bytes = reinterpret_cast<const char*>(values.data());
    data_.insert(data_.end(), bytes, bytes + values.size() * sizeof(T));
  }
  void putBytes(const char* bytes, std::size_t size) { data_.insert(data_.end(), bytes, bytes + size); }
  const std::vector<char>& data() const { return data_; }

 private:
  std::vector<char> data_;
};

// Reads what Writer wrote; every read checks the bounds, and a failed one
// leaves ok() false for good.
class Reader {
 public:
  explicit Reader(const std::vector<char>& data) : data_(data) {}
  template <class T>
  T get() {
    T value{};
    if (take(sizeof(T))) std::memcpy(&value, data_.data() + position_ - sizeof(T), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getArray(std::uint64_t expectedCount) {
    const auto count = get<std::uint64_t>();
    // Compared by division: a crafted count times sizeof(T) could wrap.
    if (count != expectedCount || count > (data_.size() - position_) / sizeof(T) || !take(count * sizeof(T))) {
      ok_ = false;
      return {};
    }
    std::vector<T> values(count);
    std::memcpy(values.data(), data_.data() + position_ - count * sizeof(T), count * sizeof(T));
    return values;
  }
  bool matches(const char* bytes, std::size_t size) {
    return take(size) && std::memcmp(data_.data() + position_ - size, bytes, size) == 0;
  }
  bool ok() const { return ok_; }
  bool atEnd() const { return position_ == data_.size(); }
  std::size_t position() const { return position_; }

 private:
  bool take(std::uint64_t size) {
    if (!ok_ || size > data_.size() - position_) return ok_ = false;
    position_ += size;
    return true;
  }
  const std::vector<char>& data_;
  std::size_t position_ = 0;
  bool ok_ = true;
};

void putLevel(Writer& w, const RadianceLevel& level) {
  w.put(std::int32_t(level.width));
  w.put(std::int32_t(level.height));
  w.put(level.alpha);
  w.putArray(level.rgb);
}

std::optional<RadianceLevel> getLevel(Reader& r) {
  RadianceLevel level;
  level.width = r.get<std::int32_t>();
  level.height = r.get<std::int32_t>();
  level.alpha = r.get<double>();
  if (level.width <= 0 || level.height <= 0) return std::nullopt;
  level.rgb = r.getArray<float>(3 * std::uint64_t(level.width) * std::uint64_t(level.height));
  return level;
}

void putTable(Writer& w, const DfgTable& table) {
  w.put(std::int32_t(table.distribution));
  w.put(std::int32_t(table.geometry));
  w.put(std::int32_t(table.size));
  w.putArray(table.scaleBias);
}

std::optional<DfgTable> getTable(Reader& r) {
  DfgTable table;
  table.distribution = r.get<std::int32_t>();
  table.geometry = r.get<std::int32_t>();
  table.size = r.get<std::int32_t>();
  if (table.size <= 0) return std::nullopt;
  table.scaleBias = r.getArray<float>(2 * std::uint64_t(table.size) * std::uint64_t(table.size));
  return table;
}

// The head every file starts with: the magic, the format and the key.
void putHead(Writer& w, const std::string& key) {
  w.putBytes(kMagic, sizeof kMagic);
  w.put(kFormatVersion);
  w.putArray(std::vector<char>(key.begin(), key.end()));
}

bool headMatches(Reader& r, const std::string& key) {
  if (!r.matches(kMagic, sizeof kMagic) || r.get<std::uint32_t>() != kFormatVersion) return false;
  const auto storedKey = r.getArray<char>(key.size());
  return r.ok() && std::string(storedKey.begin(), storedKey.end()) == key;
}

// The tail it ends with: the checksum of every byte before it, and the
// magic, which a truncated file lacks.
void putTail(Writer& w) {
  w.put(fnv1a(w.data().data(), w.data().size()));
  w.putBytes(kMagic, sizeof kMagic);
}

bool tailMatches(Reader& r, const std::vector<char>& data) {
  const std::size_t payload = r.position();
  const auto checksum = r.get<std::uint64_t>();
  return r.matches(kMagic, sizeof kMagic) && r.ok() && r.atEnd() && checksum == fnv1a(data.data(), payload);
}

std::vector<char> serialize(const PrefilteredEnvironment& env, const std::string& key) {
  Writer w;
  putHead(w, key);
  w.put(std::uint32_t(env.levels.size()));
  for (const RadianceLevel& level : env.levels) putLevel(w, level);
  for (const glm::dvec3& c : env.irradianceSh) w.put(c);
  putLevel(w, env.irradianceMap);
  w.put(std::uint8_t(env.irradianceFromMap));
  w.put(std::uint32_t(env.dfg.size()));
  for (const DfgTable& table : env.dfg) putTable(w, table);
  putTail(w);
  return w.data();
}

std::optional<PrefilteredEnvironment> deserialize(const std::vector<char>& data, const std::string& key) {
  Reader r(data);
  if (!headMatches(r, key)) return std::nullopt;
  PrefilteredEnvironment env;
  const auto levels = r.get<std::uint32_t>();
  for (std::uint32_t i = 0; i < levels && r.ok(); ++i) {
    std::optional<RadianceLevel> level = getLevel(r);
    if (!level) return std::nullopt;
    env.levels.push_back(std::move(*level));
  }
  for (glm::dvec3& c : env.irradianceSh) c = r.get<glm::dvec3>();
  std::optional<RadianceLevel> irradianceMap = getLevel(r);
  if (!irradianceMap) return std::nullopt;
  env.irradianceMap = std::move(*irradianceMap);
  const auto fromMap = r.get<std::uint8_t>();
  if (fromMap > 1) return std::nullopt;
  env.irradianceFromMap = fromMap == 1;
  const auto tables = r.get<std::uint32_t>();
  for (std::uint32_t i = 0; i < tables && r.ok(); ++i) {
    std::optional<DfgTable> table = getTable(r);
    if (!table) return std::nullopt;
    env.dfg.push_back(std::move(*table));
  }
  if (!tailMatches(r, data)) return std::nullopt;
  return env;
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

std::vector<char> serialize(const DfgTable& table, const std::string& key) {
  Writer w;
  putHead(w, key);
  putTable(w, table);
  putTail(w);
  return w.data();
}

std::optional<DfgTable> deserializeTable(const std::vector<char>& data, const std::string& key) {
  Reader r(data);
  if (!headMatches(r, key)) return std::nullopt;
  std::optional<DfgTable> table = getTable(r);
  if (!table || !tailMatches(r, data)) return std::nullopt;
  return table;
}

bool allFinite(const std::vector<float>& values) {
  return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

bool tableFits(const DfgTable& table, int distribution, int geometry, const PrefilterSettings& settings) {
  return table.distribution == distribution && table.geometry == geometry && table.size == settings.dfgSize &&
         allFinite(table.scaleBias);
}

bool levelFits(const RadianceLevel& level) { return std::isfinite(level.alpha) && allFinite(level.rgb); }

// What the renderers index without a check: a level per setting, a table
// per model pair in request order, and finite values everywhere.
bool environmentFits(const PrefilteredEnvironment& env, const ModelPairs& models, const PrefilterSettings& settings) {
  if (env.levels.size() != std::size_t(settings.levels) || env.dfg.size() != models.size()) return false;
  for (std::size_t i = 0; i < models.size(); ++i)
    if (!tableFits(env.dfg[i], models[i].first, models[i].second, settings)) return false;
  for (const glm::dvec3& c : env.irradianceSh)
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
  return std::all_of(env.levels.begin(), env.levels.end(), levelFits) && levelFits(env.irradianceMap);
}

// The stored value of `key` (file `<prefix>-<hash>.bin`) when present and
// intact, else `build`'s, stored.
template <class T, class Deserialize, class Fits, class Build>
T cached(const std::string& prefix, const std::string& key, Deserialize deserializeStored, Fits fits, Build build) {
  const std::optional<fs::path> directory = cacheDirectory();
  if (!directory) return build();
  char name[48];
  std::snprintf(name, sizeof name, "%s-%016llx.bin", prefix.c_str(), static_cast<unsigned long long>(fnv1a(key)));
  const fs::path file = *directory / name;
  try {
    if (const auto data = readFile(file))
      if (std::optional<T> stored = deserializeStored(*data, key); stored && fits(*stored)) return std::move(*stored);
  } catch (const std::exception&) {  // a file too large to hold: a miss like any other bad file
  }
  T value = build();
  writeFileAtomically(file, serialize(value, key));
  return value;
}

}  // namespace

PrefilteredEnvironment cachedPrefilter(const scene::EnvironmentMap& map, const ModelPairs& models,
                                       const PrefilterSettings& settings, const std::string& builder,
                                       const std::function<PrefilteredEnvironment()>& build) {
  return cached<PrefilteredEnvironment>(
      "prefiltered", keyText(map, models, settings, builder), deserialize,
      [&](const PrefilteredEnvironment& env) { return environmentFits(env, models, settings); }, build);
}

DfgTable cachedDfgTable(int distribution, int geometry, const PrefilterSettings& settings) {
  return cached<DfgTable>(
      "dfg", dfgKeyText(distribution, geometry, settings), deserializeTable,
      [&](const DfgTable& table) { return tableFits(table, distribution, geometry, settings); },
      [&] { return dfgTable(distribution, geometry, settings); });
}

}  // namespace facet::ibl

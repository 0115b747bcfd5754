#include "engine/ibl/prefilter_cache_format.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/ibl/cache_bytes.h"
#include "engine/ibl/prefilter_steps.h"
#include "rules/rules.h"

namespace facet::ibl::cache_format {

namespace {

constexpr char kMagic[8] = {'F', 'A', 'C', 'E', 'T', 'I', 'B', 'L'};

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

}  // namespace

std::uint64_t fnv1a(const char* bytes, std::size_t size, std::uint64_t hash) {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

std::vector<char> seal(const std::string& key, const std::vector<char>& payload) {
  Writer w;
  w.putBytes(kMagic, sizeof kMagic);
  w.put(kFormatVersion);
  w.putArray(std::vector<char>(key.begin(), key.end()));
  w.putBytes(payload.data(), payload.size());
  w.put(fnv1a(w.data().data(), w.data().size()));
  w.putBytes(kMagic, sizeof kMagic);
  return w.data();
}

std::optional<std::vector<char>> unseal(const std::vector<char>& file, const std::string& key) {
  constexpr std::size_t kTail = sizeof(std::uint64_t) + sizeof kMagic;
  Reader r(file);
  if (!r.matches(kMagic, sizeof kMagic) || r.get<std::uint32_t>() != kFormatVersion) return std::nullopt;
  const auto storedKey = r.getArray<char>(key.size());
  if (!r.ok() || std::string(storedKey.begin(), storedKey.end()) != key) return std::nullopt;
  const std::size_t first = r.position();
  if (file.size() < first + kTail) return std::nullopt;
  const std::size_t last = file.size() - kTail;
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, file.data() + last, sizeof checksum);
  if (std::memcmp(file.data() + last + sizeof checksum, kMagic, sizeof kMagic) != 0 ||
      checksum != fnv1a(file.data(), last))
    return std::nullopt;
  return std::vector<char>(file.begin() + std::ptrdiff_t(first), file.begin() + std::ptrdiff_t(last));
}

std::vector<char> environmentPayload(const PrefilteredEnvironment& env) {
  Writer w;
  w.put(std::uint32_t(env.levels.size()));
  for (const RadianceLevel& level : env.levels) putLevel(w, level);
  for (const glm::dvec3& c : env.irradianceSh) w.put(c);
  putLevel(w, env.irradianceMap);
  w.put(std::uint8_t(env.irradianceFromMap));
  w.put(std::uint32_t(env.dfg.size()));
  for (const DfgTable& table : env.dfg) putTable(w, table);
  return w.data();
}

std::optional<PrefilteredEnvironment> environmentFromPayload(const std::vector<char>& payload) {
  Reader r(payload);
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
  if (!r.ok() || !r.atEnd()) return std::nullopt;
  return env;
}

std::vector<char> tablePayload(const DfgTable& table) {
  Writer w;
  putTable(w, table);
  return w.data();
}

std::optional<DfgTable> tableFromPayload(const std::vector<char>& payload) {
  Reader r(payload);
  std::optional<DfgTable> table = getTable(r);
  if (!table || !r.ok() || !r.atEnd()) return std::nullopt;
  return table;
}

namespace {

bool allFinite(const std::vector<float>& values) {
  return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

bool levelFits(const RadianceLevel& level) { return std::isfinite(level.alpha) && allFinite(level.rgb); }

bool sized(const RadianceLevel& level, LevelSize size) {
  return level.width == size.width && level.height == size.height;
}

// The levels' shape as the prefilter makes it for `map`: a sealed file of
// another shape (a 1 x 1 level) would light the scene wrongly without a word.
bool shapeFits(const PrefilteredEnvironment& env, const scene::EnvironmentMap& map, const PrefilterSettings& settings) {
  if (!sized(env.levels.front(), {map.width, map.height}) || env.levels.front().alpha != 0.0) return false;
  if (!sized(env.irradianceMap, irradianceMapSize(settings))) return false;
  for (int i = 1; i < settings.levels; ++i) {
    const RadianceLevel& level = env.levels[std::size_t(i)];
    if (!sized(level, prefilteredLevelSize(map, settings, i)) ||
        level.alpha != rules::f64::prefiltered_level_alpha(i, settings.levels))
      return false;
  }
  return true;
}

}  // namespace

bool tableFits(const DfgTable& table, int distribution, int geometry, const PrefilterSettings& settings) {
  return table.distribution == distribution && table.geometry == geometry && table.size == settings.dfgSize &&
         allFinite(table.scaleBias);
}

bool environmentFits(const PrefilteredEnvironment& env, const scene::EnvironmentMap& map, const ModelPairs& models,
                     const PrefilterSettings& settings) {
  if (env.levels.size() != std::size_t(settings.levels) || env.dfg.size() != models.size()) return false;
  if (!shapeFits(env, map, settings)) return false;
  for (std::size_t i = 0; i < models.size(); ++i)
    if (!tableFits(env.dfg[i], models[i].first, models[i].second, settings)) return false;
  for (const glm::dvec3& c : env.irradianceSh)
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
  return std::all_of(env.levels.begin(), env.levels.end(), levelFits) && levelFits(env.irradianceMap);
}

}  // namespace facet::ibl::cache_format

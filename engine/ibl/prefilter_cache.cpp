// The disk cache of prefiltered environments and of DFG tables: one file
// per key in the cache folder (cache_folder.h), in the format of
// prefilter_cache_format.h. What a file holds must also fit the request (its
// levels, its tables, finite values) or it is rebuilt.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/ibl/cache_folder.h"
#include "engine/ibl/last_result.h"
#include "engine/ibl/prefilter_cache_format.h"
#include "engine/ibl/prefiltered_environment.h"

namespace facet::ibl {

namespace {

namespace fs = std::filesystem;

using cache_format::kFormatVersion;

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

std::string glassKeyText(double eta, bool thinWalled, const PrefilterSettings& settings) {
  std::ostringstream key;
  key << "facet glass albedo table v" << kFormatVersion << " code " << FACET_PREFILTER_FINGERPRINT << " dfgSize "
      << settings.dfgSize << " dfgSamples " << settings.dfgSamples << " eta " << std::hexfloat << eta << " thinWalled "
      << thinWalled;
  return key.str();
}

// The stored value of `key` (file `<prefix>-<hash>.bin`) when present,
// intact and fitting the request, else `build`'s, stored.
template <class T, class ToPayload, class FromPayload, class Fits, class Build>
T cached(const std::string& prefix, const std::string& key, ToPayload toPayload, FromPayload fromPayload, Fits fits,
         Build build) {
  const std::optional<fs::path> directory = cacheDirectory();
  if (!directory) return build();
  const fs::path file = cacheFile(*directory, prefix, key);
  try {
    if (const auto data = readCacheFile(file))
      if (const auto payload = cache_format::unseal(*data, key))
        if (std::optional<T> stored = fromPayload(*payload); stored && fits(*stored)) return std::move(*stored);
  } catch (const std::exception&) {  // a file too large to hold: a miss like any other bad file
  }
  T value = build();
  writeCacheFileAtomically(file, cache_format::seal(key, toPayload(value)));
  return value;
}

}  // namespace

namespace {

// cachedPrefilter under its key, which hashes every texel of the map: worked
// out once per call.
PrefilteredEnvironment cachedPrefilterOfKey(const std::string& key, const scene::EnvironmentMap& map,
                                            const ModelPairs& models, const PrefilterSettings& settings,
                                            const std::function<PrefilteredEnvironment()>& build) {
  return cached<PrefilteredEnvironment>(
      "prefiltered", key, cache_format::environmentPayload, cache_format::environmentFromPayload,
      [&](const PrefilteredEnvironment& env) { return cache_format::environmentFits(env, map, models, settings); },
      build);
}

}  // namespace

PrefilteredEnvironment cachedPrefilter(const scene::EnvironmentMap& map, const ModelPairs& models,
                                       const PrefilterSettings& settings, const std::string& builder,
                                       const std::function<PrefilteredEnvironment()>& build) {
  return cachedPrefilterOfKey(keyText(map, models, settings, builder), map, models, settings, build);
}

PrefilteredEnvironment rememberedPrefilter(const scene::EnvironmentMap& map, const ModelPairs& models,
                                           const PrefilterSettings& settings, const std::string& builder,
                                           const std::function<PrefilteredEnvironment()>& build) {
  static LastResult<std::string, PrefilteredEnvironment> last;
  const std::string key = keyText(map, models, settings, builder);
  return last.get(key, [&] { return cachedPrefilterOfKey(key, map, models, settings, build); });
}

DfgTable cachedDfgTable(int distribution, int geometry, const PrefilterSettings& settings) {
  return cached<DfgTable>(
      "dfg", dfgKeyText(distribution, geometry, settings), cache_format::tablePayload, cache_format::tableFromPayload,
      [&](const DfgTable& table) { return cache_format::tableFits(table, distribution, geometry, settings); },
      [&] { return dfgTable(distribution, geometry, settings); });
}

DfgTable cachedGlassAlbedoTable(double eta, bool thinWalled, const PrefilterSettings& settings) {
  return cached<DfgTable>(
      "glass", glassKeyText(eta, thinWalled, settings), cache_format::tablePayload, cache_format::tableFromPayload,
      [&](const DfgTable& table) {
        return cache_format::tableFits(table, rules::f64::D_GGX, rules::f64::G_SMITH_GGX_CORRELATED, settings);
      },
      [&] { return glassAlbedoTable(eta, thinWalled, settings); });
}

}  // namespace facet::ibl

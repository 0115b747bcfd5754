// Cache files (engine/ibl/prefilter_cache_format.h): any bytes, read as a
// whole file under a key and as the payload of an environment, of a DFG
// table or of parity's reference renders (analysis/reference_cache.h), give
// nothing or a value, and an environment or table is then judged by the fit
// rule: never a crash, never an allocation the bytes do not back. The seeds
// are payloads, which the format's checksum would keep a mutated whole file
// from reaching.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "analysis/reference_cache.h"
#include "engine/ibl/prefilter_cache_format.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace format = facet::ibl::cache_format;
  const std::vector<char> bytes(data, data + size);
  const std::string key = "facet fuzz key";
  facet::ibl::PrefilterSettings settings;
  settings.levels = 2;
  settings.dfgSize = 2;
  const facet::ibl::ModelPairs models{{0, 4}, {1, 6}};
  facet::scene::EnvironmentMap map;
  map.width = 32;
  map.height = 16;

  if (const auto payload = format::unseal(bytes, key)) format::environmentFromPayload(*payload);
  if (const auto env = format::environmentFromPayload(bytes)) format::environmentFits(*env, map, models, settings);
  if (const auto table = format::tableFromPayload(bytes)) format::tableFits(*table, 0, 4, settings);
  // The seed's size: two renders of 4 x 3 pixels; what reads back writes back the same.
  if (const auto reference = facet::analysis::referenceFromPayload(bytes, 4, 3, 2))
    if (facet::analysis::referencePayload(*reference) != bytes) std::abort();
  // Whatever a payload holds, sealing it and reading it back gives it again.
  const auto back = format::unseal(format::seal(key, bytes), key);
  if (!back || *back != bytes) std::abort();
  return 0;
}

#include "engine/ibl/compensation_tables.h"

#include <map>
#include <utility>

#include "materials/material.h"
#include "rules/rules.h"

namespace facet::ibl {

// The split sum's grid at a quarter of its samples per entry: what the
// grid's interpolation leaves dominates the error either way, and every
// (D, G) pair's compensated furnace stays within 1% at n.v >= 0.1, chosen by
// measurement (docs/shading.md, "Energy compensation").
PrefilterSettings compensationTableSettings() {
  PrefilterSettings settings;
  settings.dfgSamples = 1024;
  return settings;
}

CompensationTables compensationTables(const scene::Scene& scene) {
  CompensationTables result;
  const PrefilterSettings settings = compensationTableSettings();
  // Each table, or a glass's pair of tables, built once: keyed by the (D, G)
  // pair, or by the glass's index and wall.
  std::map<std::pair<int, int>, int> firstOfPair;
  std::map<std::pair<double, bool>, int> firstOfGlass;
  for (const materials::Material& material : scene.materials) {
    if (!material.energyCompensation) {
      result.tableOfMaterial.push_back(CompensationTables::kNone);
      continue;
    }
    const int next = int(result.tables.size());
    if (materials::isTransmissive(material)) {
      const auto [entry, added] = firstOfGlass.try_emplace({material.eta.x, material.thinWalled}, next);
      if (added) {
        const auto table = [&](bool outside) {
          return cachedGlassAlbedoTable(rules::f64::transmissive_eta(material.eta.x, material.thinWalled, outside),
                                        material.thinWalled, settings);
        };
        result.tables.push_back(table(true));
        // A thin wall's one interface is the same from either side.
        result.tables.push_back(material.thinWalled ? result.tables.back() : table(false));
      }
      result.tableOfMaterial.push_back(entry->second);
    } else {
      const auto [entry, added] = firstOfPair.try_emplace({material.distribution, material.geometry}, next);
      if (added) result.tables.push_back(cachedDfgTable(material.distribution, material.geometry, settings));
      result.tableOfMaterial.push_back(entry->second);
    }
  }
  return result;
}

glm::dvec3 specularScale(const CompensationTables& tables, int material, const rules::f64::BrdfParams& params,
                         double nv, bool transmissive, bool outside) {
  const int first = tables.tableOfMaterial[std::size_t(material)];
  if (first == CompensationTables::kNone) return glm::dvec3(1.0);
  const DfgTable& table = tables.tables[std::size_t(rules::f64::compensation_table(first, transmissive, outside))];
  return rules::f64::material_compensation(params, transmissive,
                                           dfgLookup(table, nv, rules::f64::isotropic_equivalent_alpha(params)));
}

}  // namespace facet::ibl

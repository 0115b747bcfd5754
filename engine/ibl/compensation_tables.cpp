#include "engine/ibl/compensation_tables.h"

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
  ModelPairs pairs;
  for (const materials::Material& material : scene.materials)
    result.tableOfMaterial.push_back(material.energyCompensation ? modelPairIndex(pairs, material)
                                                                 : CompensationTables::kNone);
  for (const auto& [distribution, geometry] : pairs)
    result.tables.push_back(cachedDfgTable(distribution, geometry, compensationTableSettings()));
  return result;
}

glm::dvec3 specularScale(const CompensationTables& tables, int material, const rules::f64::BrdfParams& params,
                         double nv) {
  const int table = tables.tableOfMaterial[std::size_t(material)];
  if (table == CompensationTables::kNone) return glm::dvec3(1.0);
  return rules::f64::specular_compensation(
      params, dfgLookup(tables.tables[std::size_t(table)], nv, rules::f64::isotropic_equivalent_alpha(params)));
}

}  // namespace facet::ibl

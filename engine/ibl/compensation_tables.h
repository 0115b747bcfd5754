// Energy compensation's albedo tables (docs/shading.md, "Energy
// compensation"): one DFG table per (D, G) pair of the scene's compensated
// opaque materials, built like the split sum's, and two glass albedo tables
// per index and wall of its compensated transmissive ones (the interface
// seen from outside, then from inside), read alike by both backends. A scene
// with no compensated material builds none.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

#include "engine/ibl/prefiltered_environment.h"
#include "scenes/scene.h"

namespace facet::ibl {

struct CompensationTables {
  static constexpr int kNone = -1;
  std::vector<DfgTable> tables;
  std::vector<int> tableOfMaterial;  // per scene material: index of its (first) table, or kNone
};

// The size and samples of each table (dfgSize, dfgSamples).
PrefilterSettings compensationTableSettings();

CompensationTables compensationTables(const scene::Scene& scene);

// The factor on scene material `material`'s specular lobe (a transmissive
// one's dielectric lobes), parameters `params` after its textures, seen at
// n.v = nv from outside or not: vec3(1) when the material is not compensated.
glm::dvec3 specularScale(const CompensationTables& tables, int material, const rules::f64::BrdfParams& params,
                         double nv, bool transmissive, bool outside);

}  // namespace facet::ibl

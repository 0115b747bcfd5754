// The white furnace with multiple-scattering compensation, for a DFG table
// built on either backend.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "rules/rules.h"
#include "engine/ibl/prefiltered_environment.h"
#include "materials/albedo.h"

namespace facet::ibl::testing {

// With F = 1 (Schlick, F0 = 1) the compensated lobe must reflect everything:
// the exact single-scattering albedo (materials/albedo.h) times the factor
// read from `table`. Returns the worst |E - 1| over n.v in [minNv, 1] and
// sqrt(alpha) in (0, 1], at points between the table's entries and at the
// ends (alpha = 1, n.v = minNv, n.v = 1).
inline double compensatedFurnaceError(const DfgTable& table, double minNv) {
  namespace m = rules::f64;
  std::vector<double> nvs, roughnesses;
  for (double nv = minNv; nv < 1.0; nv += 0.0617) nvs.push_back(nv);
  for (double roughness = 0.013; roughness < 1.0; roughness += 0.0571) roughnesses.push_back(roughness);
  nvs.push_back(1.0);
  roughnesses.push_back(1.0);
  double worst = 0, worstNv = 0, worstRoughness = 0;
  for (const double nv : nvs)
    for (const double roughness : roughnesses) {
      const m::BrdfParams params{table.distribution, table.geometry,  m::F_SCHLICK,    roughness * roughness,
                                 glm::dvec3(1.0),    glm::dvec3(1.0), glm::dvec3(0.0), 0.0,
                                 glm::dvec3(0.0)};
      const double single = materials::directionalAlbedo(params, nv, 128).specular.x;
      const double factor = m::energy_compensation(params.f0, dfgLookup(table, nv, params.alpha)).x;
      const double error = std::abs(single * factor - 1);
      if (error > worst) worst = error, worstNv = nv, worstRoughness = roughness;
    }
  std::printf("D %d G %d: compensated furnace, worst |E - 1| = %.3g for n.v >= %.2f (at n.v %.3f, sqrt(alpha) %.3f)\n",
              table.distribution, table.geometry, worst, minNv, worstNv, worstRoughness);
  return worst;
}

}  // namespace facet::ibl::testing

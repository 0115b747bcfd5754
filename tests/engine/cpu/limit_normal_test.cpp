// The limit normal's fallback where the partial derivatives' cross product
// vanishes (engine/cpu/limit_normal.h over rules/surface/limit_normal.h).
#include "engine/cpu/limit_normal.h"
#include "rules/rules.h"
#include "tests/support/cpu_intersect.h"

#include <gtest/gtest.h>

#include <iostream>

namespace facet::cpu {
namespace {

using testing::angleBetween;
using testing::Geometry;

// Patch corners where dP/du x dP/dv vanishes (OpenSubdiv #947, #1352): in
// creased_box where an infinitely sharp crease turns a corner (dP/du and
// dP/dv parallel), in suzanne at end-cap corners where both derivatives are
// zero. The fallback must give a unit normal continuous with the normals
// just inside the patch.
TEST(LimitNormal, FallsBackWhereTheCrossProductVanishes) {
  for (const std::string& name : {std::string("creased_box"), std::string("suzanne")}) {
    Geometry geometry(name);
    int degenerate = 0;
    for (int patch = 0; patch < geometry.surface.patchCount(); ++patch) {
      const scene::PatchDomain& domain = geometry.surface.patch(patch).domain;
      for (int corner = 0; corner < 4; ++corner) {
        const double s = corner & 1, t = corner >> 1;
        const double u = domain.u0 + s * domain.size, v = domain.v0 + t * domain.size;
        const scene::LimitPoint point = geometry.surface.evaluatePatch(patch, u, v);
        glm::dvec3 unused;
        if (rules::f64::well_defined_normal(point.du, point.dv, unused)) continue;
        ++degenerate;
        const glm::dvec3 normal = limitNormal(geometry.surface, patch, u, v);
        EXPECT_NEAR(glm::length(normal), 1.0, 1e-12);
        const double inward = 1e-4 * domain.size;
        const glm::dvec3 inside =
            limitNormal(geometry.surface, patch, u + (s == 0.0 ? inward : -inward), v + (t == 0.0 ? inward : -inward));
        EXPECT_LT(angleBetween(normal, inside), 0.05) << name << " patch " << patch << " corner " << corner;
      }
    }
    EXPECT_GT(degenerate, 0) << name << ": no degenerate point, the fallback went untested";
    std::cout << name << ": " << degenerate << " patch corners with a vanishing cross product\n";
  }
}

}  // namespace
}  // namespace facet::cpu

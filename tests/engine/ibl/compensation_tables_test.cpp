// Energy compensation's tables (engine/ibl/compensation_tables.h): built for
// the compensated materials' (D, G) pairs only, read as the factor of
// rules/shading/dfg.h.
#include <gtest/gtest.h>

#include "engine/ibl/compensation_tables.h"
#include "rules/rules.h"
#include "materials/material.h"
#include "tests/support/compensated_furnace.h"

namespace facet::ibl {
namespace {

namespace m = rules::f64;

materials::Material material(int distribution, bool compensated) {
  materials::Material result;
  result.distribution = distribution;
  result.f0 = glm::dvec3(1.0);
  result.alpha = 0.49;
  result.energyCompensation = compensated;
  return result;
}

TEST(CompensationTables, OneTablePerPairOfTheCompensatedMaterials) {
  scene::Scene scene;
  EXPECT_TRUE(compensationTables(scene).tables.empty());
  scene.materials = {material(m::D_GGX, true), material(m::D_BECKMANN, false), material(m::D_GGX, true)};
  const CompensationTables tables = compensationTables(scene);
  ASSERT_EQ(tables.tables.size(), 1u);
  EXPECT_EQ(tables.tables[0].distribution, m::D_GGX);
  EXPECT_EQ(tables.tableOfMaterial, (std::vector<int>{0, CompensationTables::kNone, 0}));

  // Uncompensated: exactly the course's lobe. Compensated with F(0) = 1: the
  // inverse of the lobe's albedo, above 1 for a rough lobe.
  const m::BrdfParams params = materials::toParams64(scene.materials[0]);
  EXPECT_EQ(specularScale(tables, 1, params, 0.5), glm::dvec3(1.0));
  const glm::dvec2 dfg = dfgLookup(tables.tables[0], 0.5, params.alpha);
  const glm::dvec3 factor = specularScale(tables, 0, params, 0.5);
  EXPECT_NEAR(factor.x, 1.0 / (dfg.x + dfg.y), 1e-12);
  EXPECT_GT(factor.x, 1.05);
  // With F(0) = 0.04 the added energy shrinks with F(0) (Turquin 2019).
  m::BrdfParams dielectric = params;
  dielectric.f0 = glm::dvec3(0.04);
  const glm::dvec3 small = specularScale(tables, 0, dielectric, 0.5);
  EXPECT_NEAR(small.x - 1.0, 0.04 * (factor.x - 1.0), 1e-12);
}

// The bound, E = 1 within 1% for F(0) = 1 at every alpha and
// n.v >= 0.1, for the tables as the renderers build them: the default pair,
// and the implicit G, whose albedo bends fastest near n.v = 0.1 and so
// leaves the grid's interpolation its largest error.
TEST(CompensationTables, CompensatedFurnaceWithinOnePercent) {
  scene::Scene scene;
  scene.materials = {material(m::D_GGX, true), material(m::D_GGX, true)};
  scene.materials[1].geometry = m::G_IMPLICIT;
  const CompensationTables tables = compensationTables(scene);
  ASSERT_EQ(tables.tables.size(), 2u);
  for (const DfgTable& table : tables.tables) EXPECT_LT(testing::compensatedFurnaceError(table, 0.1), 1e-2);
}

}  // namespace
}  // namespace facet::ibl

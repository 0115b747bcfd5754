// Energy compensation's tables (engine/ibl/compensation_tables.h): built for
// the compensated materials' (D, G) pairs and glasses only, read as the
// factor of rules/shading/dfg.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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
  EXPECT_EQ(specularScale(tables, 1, params, 0.5, false, true), glm::dvec3(1.0));
  const glm::dvec2 dfg = dfgLookup(tables.tables[0], 0.5, params.alpha);
  const glm::dvec3 factor = specularScale(tables, 0, params, 0.5, false, true);
  EXPECT_NEAR(factor.x, 1.0 / (dfg.x + dfg.y), 1e-12);
  EXPECT_GT(factor.x, 1.05);
  // With F(0) = 0.04 the added energy shrinks with F(0) (Turquin 2019).
  m::BrdfParams dielectric = params;
  dielectric.f0 = glm::dvec3(0.04);
  const glm::dvec3 small = specularScale(tables, 0, dielectric, 0.5, false, true);
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

materials::Material glass(double ior, bool thinWalled) {
  materials::Material result;
  result.fresnel = m::F_DIELECTRIC;
  result.eta = glm::dvec3(ior);
  result.transmission = 1;
  result.thinWalled = thinWalled;
  result.alpha = 0.25;
  result.energyCompensation = true;
  return result;
}

// A glass's two tables (its interface from outside and from inside) follow
// in order, one pair per index and wall, and are read by the side the hit is
// seen from as 1 / E.
TEST(CompensationTables, TwoGlassTablesPerIndexAndWall) {
  scene::Scene scene;
  scene.materials = {glass(1.5, false), material(m::D_GGX, true), glass(1.5, false), glass(1.5, true),
                     glass(2.4, false)};
  const CompensationTables tables = compensationTables(scene);
  ASSERT_EQ(tables.tables.size(), 7u);
  EXPECT_EQ(tables.tableOfMaterial, (std::vector<int>{0, 2, 0, 3, 5}));
  const m::BrdfParams params = materials::toParams64(scene.materials[0]);
  for (const bool outside : {true, false}) {
    const double e = dfgLookup(tables.tables[outside ? 0 : 1], 0.5, params.alpha).x;
    EXPECT_NEAR(specularScale(tables, 0, params, 0.5, true, outside).x, 1.0 / e, 1e-12);
    // glTF's metal share takes the factor in proportion to the interface's share.
    m::BrdfParams metallic = params;
    metallic.metallic = 0.25;
    EXPECT_NEAR(specularScale(tables, 0, metallic, 0.5, true, outside).x, 1.0 + 0.75 * (1.0 / e - 1.0), 1e-12);
    EXPECT_LT(e, 0.99);  // a rough interface loses energy from either side
  }
  // From inside, rays beyond the critical angle reflect in full: another table.
  EXPECT_NE(dfgLookup(tables.tables[0], 0.3, params.alpha).x, dfgLookup(tables.tables[1], 0.3, params.alpha).x);
  // A thin wall's interface has the same index on both sides.
  EXPECT_EQ(tables.tables[3].scaleBias, tables.tables[4].scaleBias);
}

// Compensated, a clear rough interface keeps all it receives: the
// interface's albedo at points between the table's entries (and at the
// ends), integrated anew with 16 times the table's samples, times the
// factor read from the table, is 1 within 1% for n.v >= 0.1, from either
// side and through a thin wall.
TEST(CompensationTables, CompensatedGlassFurnaceWithinOnePercent) {
  scene::Scene scene;
  scene.materials = {glass(1.5, false), glass(1.5, true)};
  const CompensationTables tables = compensationTables(scene);
  ASSERT_EQ(tables.tables.size(), 4u);
  const int samples = 16 * compensationTableSettings().dfgSamples;
  for (int table = 0; table < 3; ++table) {
    const double eta = table == 1 ? 1 / 1.5 : 1.5;
    double worst = 0;
    for (double nv = 0.1; nv <= 1.0; nv += 0.1234)
      for (double roughness = 0.013; roughness <= 1.0; roughness += 0.0771) {
        const double alpha = roughness * roughness;
        const double e = m::glass_albedo_entry(nv, alpha, eta, table == 2, samples).x;
        worst = std::max(worst, std::abs(e / dfgLookup(tables.tables[table], nv, alpha).x - 1));
      }
    std::printf("glass table %d (eta %.4f%s): compensated furnace, worst |E - 1| = %.3g\n", table, eta,
                table == 2 ? ", thin" : "", worst);
    EXPECT_LT(worst, 1e-2);
  }
}

}  // namespace
}  // namespace facet::ibl

// Energy compensation's tables (engine/ibl/compensation_tables.h): built for
// the compensated materials' (D, G) pairs only, read as the factor of
// rules/shading/dfg.h; and the sheen's albedo table, read by the layering of
// rules/shading/sheen.h.
#include <gtest/gtest.h>

#include "engine/ibl/compensation_tables.h"
#include "rules/rules.h"
#include "materials/material.h"
#include "tests/support/compensated_furnace.h"
#include "materials/albedo.h"

#include <cmath>
#include <cstdio>
#include <numbers>

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

// The whole layer's directional albedo at mu for color 1 over a Lambert
// base of albedo `white` (0: the sheen alone), each direction's E looked up
// in `table` as the renderers do: Gauss-Legendre in cos(theta_l) and
// azimuth.
double layeredAlbedo(const DfgTable& table, double alpha, double mu, double white) {
  static const materials::QuadratureRule polar = materials::gaussLegendre01(192),
                                         azimuth = materials::gaussLegendre01(128);
  const glm::dvec3 n(0, 0, 1), v(std::sqrt(1 - mu * mu), 0, mu);
  m::BrdfParams black{};  // a base of index 1 (no interface) that diffuses `white`
  black.f_model = m::F_DIELECTRIC;
  black.eta = glm::dvec3(1.0);
  black.diffuse = glm::dvec3(white);
  const m::SheenParams sheen{glm::dvec3(1.0), alpha};
  const double e_v = sheenAlbedo(table, mu, alpha);
  double sum = 0;
  for (std::size_t i = 0; i < polar.nodes.size(); ++i) {
    const double cos_l = polar.nodes[i], sin_l = std::sqrt(1 - cos_l * cos_l);
    const double e_l = sheenAlbedo(table, cos_l, alpha);
    double ring = 0;
    for (std::size_t j = 0; j < azimuth.nodes.size(); ++j) {
      const double phi = std::numbers::pi * azimuth.nodes[j];
      const glm::dvec3 l(sin_l * std::cos(phi), sin_l * std::sin(phi), cos_l);
      ring += azimuth.weights[j] * m::sheen_evaluate(black, sheen, n, l, v, glm::dvec3(1.0), e_v, e_l).x;
    }
    sum += polar.weights[i] * 2 * std::numbers::pi * ring * cos_l;
  }
  return sum;
}

TEST(SheenAlbedoTable, LookupsFollowTheLobesAlbedo) {
  // Between the grid's entries (roughness and n.v off the grid), as the
  // renderers build the table: within 1% or 0.005 of the Hammersley sum at
  // 16 times the table's samples.
  const DfgTable table = sheenAlbedoTable();
  EXPECT_EQ(table.distribution, m::SHEEN_ALBEDO_TABLE);
  double worst = 0;
  for (double roughness : {0.13, 0.37, 0.71, 0.95})
    for (double mu : {0.12, 0.33, 0.58, 0.91}) {
      const double alpha = roughness * roughness;
      const double lookup = sheenAlbedo(table, mu, alpha);
      const double exact = m::sheen_albedo_entry(mu, alpha, 16 * sheenTableSettings().dfgSamples).x;
      EXPECT_NEAR(lookup, exact, std::max(0.005, 0.01 * exact)) << "roughness " << roughness << " mu " << mu;
      worst = std::max(worst, std::abs(lookup - exact));
    }
  std::printf("sheen albedo table: largest |lookup - entry| %.2g\n", worst);
}

TEST(SheenAlbedoTable, WhiteFurnaceStaysAtMostOne) {
  // The sheen alone reflects min(E, 1) at most, and over a white Lambert
  // base the layering leaves the base what the sheen takes: at most 1 each
  // (within the quadrature's and the lookups' error), and no dimmer than
  // the base alone head-on where the sheen is faint.
  const DfgTable table = sheenAlbedoTable();
  double highest_alone = 0, highest_white = 0;
  for (double roughness : {0.07, 0.3, 0.6, 1.0})
    for (double mu : {0.05, 0.2, 0.5, 1.0}) {
      const double alpha = roughness * roughness;
      const double alone = layeredAlbedo(table, alpha, mu, 0.0), white = layeredAlbedo(table, alpha, mu, 1.0);
      EXPECT_LE(alone, 1.0 + 2e-3) << "roughness " << roughness << " mu " << mu;
      EXPECT_LE(white, 1.0 + 2e-3) << "roughness " << roughness << " mu " << mu;
      EXPECT_GT(white, 0.6) << "roughness " << roughness << " mu " << mu;
      highest_alone = std::max(highest_alone, alone);
      highest_white = std::max(highest_white, white);
      std::printf("sheen roughness %.2f mu %.2f: alone %.5f, over white Lambert %.5f\n", roughness, mu, alone, white);
    }
  std::printf("sheen furnace: highest alone %.5f, over white %.5f\n", highest_alone, highest_white);
}

}  // namespace
}  // namespace facet::ibl

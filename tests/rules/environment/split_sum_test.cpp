// Where the prefiltered method reads and how it chooses
// (rules/environment/split_sum.h): nothing under the horizon, the coat's
// lookups only under a coat and about its own normal, and the choice between
// the bare and the coated split sum made by the material alone.
#include <gtest/gtest.h>

#include "rules/rules.h"
#include "tests/support/shading_frame.h"
#include "tests/support/brdf_params.h"

namespace facet::rules {
namespace {

using facet::testing::kN;
namespace m = f64;

m::BrdfParams base() { return facet::testing::schlickBase(0.3, glm::dvec3(0.04), {0.4, 0.5, 0.6}); }

TEST(SplitSum, NothingIsReadUnderTheHorizon) {
  EXPECT_FALSE(m::split_sum_lookups(base(), kN, glm::normalize(glm::dvec3(1, 0, 1e-6))).visible);
  EXPECT_TRUE(m::split_sum_lookups(base(), kN, glm::normalize(glm::dvec3(1, 0, 1))).visible);
}

TEST(SplitSum, TheCoatIsReadOnlyUnderACoatAboutItsOwnNormal) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.5, 0, 1));
  m::BrdfParams p = base();
  EXPECT_FALSE(m::split_sum_lookups(p, kN, v).coated);
  p.clearcoat = 1.0;
  p.clearcoat_alpha = 0.0;
  p.clearcoat_normal = glm::normalize(glm::dvec3(0.2, 0, 1));
  const m::SplitSumLookups l = m::split_sum_lookups(p, kN, v);
  ASSERT_TRUE(l.coated);
  EXPECT_EQ(l.nv_coat, glm::dot(p.clearcoat_normal, v));
  const glm::dvec3 mirror = glm::reflect(-v, p.clearcoat_normal);  // alpha 0: the mirror direction
  EXPECT_NEAR(glm::length(l.coat_lobe - mirror), 0.0, 1e-12);
}

TEST(SplitSum, TheMaterialChoosesTheBareOrTheCoatedSum) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.5, 0, 1));
  const glm::dvec3 prefiltered(1.0, 0.8, 0.6), irradiance(0.3), scale(1.0), coatPrefiltered(2.0);
  const glm::dvec2 dfg(0.9, 0.05), coatDfg(0.95, 0.02);
  m::BrdfParams p = base();
  m::SplitSumLookups l = m::split_sum_lookups(p, kN, v);
  EXPECT_EQ(m::environment_split_sum(p, l, prefiltered, dfg, irradiance, scale, coatPrefiltered, coatDfg),
            m::split_sum(p, l.nv, prefiltered, dfg, irradiance, scale));
  p.clearcoat = 0.7;
  p.clearcoat_alpha = 0.05;
  l = m::split_sum_lookups(p, kN, v);
  EXPECT_EQ(m::environment_split_sum(p, l, prefiltered, dfg, irradiance, scale, coatPrefiltered, coatDfg),
            m::coated_split_sum(p, l.nv, prefiltered, dfg, irradiance, scale, l.nv_coat, coatPrefiltered, coatDfg));
}

}  // namespace
}  // namespace facet::rules

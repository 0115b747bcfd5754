// The cutout decision of glTF's alphaMode MASK (rules/surface/cutout.h), in
// both precisions.
#include <gtest/gtest.h>

#include "rules/rules.h"

namespace facet {
namespace {

TEST(Cutout, ThePresentPartIsWhereAlphaReachesTheCutoff) {
  for (double cutoff : {0.25, 0.5, 0.75}) {
    EXPECT_TRUE(rules::f64::cutout_present(1.0, cutoff, cutoff));  // at the cutoff: present
    EXPECT_FALSE(rules::f64::cutout_present(1.0, cutoff - 1e-9, cutoff));
    EXPECT_TRUE(rules::f32::cutout_present(1.0f, float(cutoff), float(cutoff)));
    // The factor scales the texture's alpha.
    EXPECT_EQ(rules::f64::cutout_present(0.5, 1.0, cutoff), cutoff <= 0.5);
    EXPECT_EQ(rules::f64::cutout_present(1.0, 0.5, cutoff), cutoff <= 0.5);
  }
  // A cutoff of 0 keeps every hit, even of alpha 0: opaque.
  EXPECT_TRUE(rules::f64::cutout_present(0.0, 0.0, 0.0));
  EXPECT_TRUE(rules::f32::cutout_present(0.0f, 0.0f, 0.0f));
}

TEST(Cutout, ItsFootprintReadsTheFinestLevel) {
  // No coordinate partials: the level of detail is the lowest there is, so
  // the lookup magnifies level 0 whatever the texture's size.
  const rules::f64::TextureFootprint f = rules::f64::cutout_footprint({0.3, 0.7});
  EXPECT_EQ(f.uv, glm::dvec2(0.3, 0.7));
  for (int size : {1, 64, 16384}) {
    const rules::f64::SlotLookup l = rules::f64::slot_lookup(f, glm::dvec2(0.1), 1.0, 0.0, glm::dvec2(2.0), size, size);
    EXPECT_LE(l.lod, 0.0);
    EXPECT_EQ(rules::f64::mip_taps(l.lod, 15, rules::f64::FACET_FILTER_NEAREST, rules::f64::FACET_FILTER_LINEAR,
                                   rules::f64::FACET_MIP_LINEAR)
                  .level0,
              0);
  }
  EXPECT_LE(rules::f32::slot_lookup(rules::f32::cutout_footprint({0.3f, 0.7f}), glm::vec2(0.0f), 1.0f, 0.0f,
                                    glm::vec2(1.0f), 64, 64)
                .lod,
            0.0f);
}

}  // namespace
}  // namespace facet

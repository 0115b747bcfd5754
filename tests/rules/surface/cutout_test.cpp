// The decisions of glTF's alphaMode MASK and BLEND (rules/surface/cutout.h),
// in both precisions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

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

TEST(Blend, ARayFindsTheSurfaceWithProbabilityAlpha) {
  // Over many rays (camera samples of many pixels) the share of hits that
  // find the surface is alpha, within four standard errors; 0 and 1 decide
  // every ray.
  constexpr int kRays = 40000;
  for (double alpha : {0.0, 0.1, 0.5, 0.93, 1.0}) {
    int present = 0;
    for (std::uint32_t ray = 0; ray < kRays; ++ray) {
      const std::uint32_t key = rules::f64::pass_through_key(ray / 16, ray % 16, 7u, rules::f64::PASS_THROUGH_NEAREST);
      present += rules::f64::blend_present(alpha, key, 2u, 11u);
    }
    EXPECT_NEAR(double(present) / kRays, alpha, 4.0 * std::sqrt(alpha * (1 - alpha) / kRays) + 1e-12) << alpha;
  }
}

TEST(Blend, TheDecisionsOfRaysAndPatchesAreIndependent) {
  // Two layers of alpha 1/2 (two patches, or two objects) let a quarter of
  // the rays through; a shadow ray decides apart from its camera ray, and
  // each vertex's rays apart from the last's.
  constexpr int kRays = 40000;
  int bothPatches = 0, bothObjects = 0, cameraAndShadow = 0, twoVertices = 0;
  for (std::uint32_t ray = 0; ray < kRays; ++ray) {
    const std::uint32_t pixel = ray / 16, sample = ray % 16;
    const std::uint32_t camera = rules::f64::pass_through_key(pixel, sample, 7u, rules::f64::PASS_THROUGH_NEAREST);
    const std::uint32_t shadow = rules::f64::pass_through_key(pixel, sample, 7u, 0u);
    const std::uint32_t next = rules::f64::pass_through_key(pixel, sample, rules::f64::path_vertex_seed(7u, 2u),
                                                            rules::f64::PASS_THROUGH_NEAREST);
    const bool first = rules::f64::blend_present(0.5, camera, 0u, 3u);
    bothPatches += !first && !rules::f64::blend_present(0.5, camera, 0u, 4u);
    bothObjects += !first && !rules::f64::blend_present(0.5, camera, 1u, 3u);
    cameraAndShadow += !first && !rules::f64::blend_present(0.5, shadow, 0u, 3u);
    twoVertices += !first && !rules::f64::blend_present(0.5, next, 0u, 3u);
  }
  const double bound = 4.0 * std::sqrt(0.25 * 0.75 / kRays);
  for (int through : {bothPatches, bothObjects, cameraAndShadow, twoVertices})
    EXPECT_NEAR(double(through) / kRays, 0.25, bound);
}

TEST(Blend, BothPrecisionsDecideAlike) {
  // The key is integer arithmetic and the number exact in float, so the
  // backends part only where alpha itself rounds differently.
  for (std::uint32_t ray = 0; ray < 5000; ++ray) {
    const std::uint32_t key = rules::f64::pass_through_key(ray, ray % 5, 0x1234u, ray % 7);
    ASSERT_EQ(key, rules::f32::pass_through_key(ray, ray % 5, 0x1234u, ray % 7));
    ASSERT_EQ(rules::f64::blend_present(0.375, key, ray % 3, ray % 11),
              rules::f32::blend_present(0.375f, key, ray % 3, ray % 11));
  }
}

}  // namespace
}  // namespace facet

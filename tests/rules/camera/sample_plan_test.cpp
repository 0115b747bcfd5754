// The camera samples of rules/camera/camera_samples.h: the centre ray
// first, then per pixel the points of an Owen-scrambled net, a different one
// per pixel of the full image.
#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

#include "rules/rules.h"

namespace facet::rules::f64 {
namespace {

std::vector<glm::dvec2> shadedOffsets(uint pixel, uint strata, uint seed = 0) {
  std::vector<glm::dvec2> offsets;
  for (uint s = first_shaded_sample(strata); s < rays_per_pixel(strata); ++s)
    offsets.push_back(sample_offset(pixel, s, strata, seed));
  return offsets;
}

TEST(SamplePlan, SampleZeroPassesThroughThePixelCentre) {
  for (uint pixel : {0u, 7u, 123456u})
    for (uint seed : {0u, 1u, 77u}) EXPECT_EQ(sample_offset(pixel, 0, 4, seed), glm::dvec2(0.5));
}

// 16 samples: one in every elementary box of area 1/16 (2^a x 2^b, a + b = 4).
TEST(SamplePlan, SixteenSamplesAreANetInEveryPixel) {
  for (uint pixel : {0u, 1u, 640u, 99999u}) {
    const std::vector<glm::dvec2> offsets = shadedOffsets(pixel, 4);
    ASSERT_EQ(offsets.size(), 16u);
    for (int a = 0; a <= 4; ++a) {
      std::set<std::pair<int, int>> boxes;
      for (const glm::dvec2& o : offsets) {
        ASSERT_GE(o.x, 0.0);
        ASSERT_LT(o.x, 1.0);
        ASSERT_GE(o.y, 0.0);
        ASSERT_LT(o.y, 1.0);
        boxes.insert({int(o.x * (1 << a)), int(o.y * (1 << (4 - a)))});
      }
      EXPECT_EQ(boxes.size(), 16u) << "pixel " << pixel << ", boxes " << (1 << a) << " x " << (1 << (4 - a));
    }
  }
}

// 9 samples draw 9 points of a 16-point net: never two in one 4 x 4 stratum.
TEST(SamplePlan, NineSamplesKeepTheirStrata) {
  std::set<std::pair<int, int>> strata;
  for (const glm::dvec2& o : shadedOffsets(42, 3)) strata.insert({int(o.x * 4), int(o.y * 4)});
  EXPECT_EQ(strata.size(), 9u);
}

// Neighbouring pixels, and pixels a row apart, scramble their nets apart.
TEST(SamplePlan, PixelsDrawDifferentPoints) {
  const std::vector<glm::dvec2> first = shadedOffsets(1000, 2);
  for (uint other : {1001u, 1000u + 640u})
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_NE(first[i], shadedOffsets(other, 2)[i]) << other;
}

// Each seed scrambles its own net, still one sample in every box of 1/16.
TEST(SamplePlan, EachSeedDrawsANetOfItsOwn) {
  const std::vector<glm::dvec2> first = shadedOffsets(1000, 4, 0);
  for (uint seed : {1u, 2u, 1000u}) {
    const std::vector<glm::dvec2> other = shadedOffsets(1000, 4, seed);
    std::set<std::pair<int, int>> boxes;
    for (std::size_t i = 0; i < first.size(); ++i) {
      EXPECT_NE(first[i], other[i]) << "seed " << seed;
      boxes.insert({int(other[i].x * 4), int(other[i].y * 4)});
    }
    EXPECT_EQ(boxes.size(), 16u) << "seed " << seed;
  }
}

}  // namespace
}  // namespace facet::rules::f64

// Image errors on hand-made images whose answers are known, and the one
// rule for a covered pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/image_compare.h"

namespace facet::analysis {
namespace {

// A 9x9 image whose centre 5x5 square is a surface at depth 10 facing the eye.
Image square() {
  Image image(9, 9);
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    const int x = int(p % 9), y = int(p / 9);
    if (std::min(x, y) < 2 || std::max(x, y) > 6) continue;
    image.beauty[p] = {0.5f, 0.5f, 0.5f, 1.0f};
    image.depth[p] = 10.0f;
    image.shadingNormal[p] = {0.0f, 0.0f, 1.0f};
    image.patchId[p] = 3;
  }
  return image;
}

TEST(CoveredPixel, IsWhereTheCentreRayHitNotWhereAlphaIsAboveZero) {
  Image image = square();
  // Several samples per pixel: some hit where the centre ray missed.
  image.beauty[image.index(0, 0)].a = 0.25f;
  EXPECT_FALSE(covered(image, 0, 0));
  EXPECT_TRUE(covered(image, 4, 4));
  image.beauty[image.index(4, 4)].a = 0.0f;
  EXPECT_TRUE(covered(image, 4, 4));
  EXPECT_TRUE(covered(10.0f));
  EXPECT_FALSE(covered(INFINITY));
}

TEST(CoveredPixel, SilhouettesAndInteriorFollowTheNeighbourhood) {
  const Image image = square();
  EXPECT_TRUE(onSilhouette(image, 2, 2));  // a corner of the square
  EXPECT_TRUE(onSilhouette(image, 1, 4));  // missed, beside the square
  EXPECT_FALSE(onSilhouette(image, 4, 4));
  EXPECT_FALSE(onSilhouette(image, 0, 0));
  EXPECT_TRUE(interior(image, image, 3, 3));
  EXPECT_FALSE(interior(image, image, 2, 3));
}

TEST(ImageError, IdenticalImagesHaveNoError) {
  const ImageError e = compareToReference(square(), square());
  EXPECT_EQ(e.compared, 25u);
  EXPECT_EQ(e.relativeRmse, 0.0);
  EXPECT_EQ(e.depthRelativeMax, 0.0);
  EXPECT_EQ(e.normalRadiansMax, 0.0);
  EXPECT_EQ(e.holes + e.extra + e.nonFinite, 0u);
}

TEST(ImageError, KnownBeautyDepthAndNormalErrors) {
  Image candidate = square();
  // Every covered pixel 0.1 brighter: RMSE 0.1 over a mean of 0.5.
  for (std::size_t p = 0; p < candidate.pixelCount(); ++p)
    if (covered(candidate, p)) candidate.beauty[p] += glm::vec4(0.1f, 0.1f, 0.1f, 0.0f);
  // One pixel 1% deeper, its normal turned by 0.1 rad.
  const std::size_t p = candidate.index(4, 4);
  candidate.depth[p] = 10.1f;
  candidate.shadingNormal[p] = {std::sin(0.1f), 0.0f, std::cos(0.1f)};
  const ImageError e = compareToReference(candidate, square());
  EXPECT_NEAR(e.relativeRmse, 0.2, 1e-6);
  EXPECT_NEAR(e.maxAbsolute, 0.1, 1e-6);
  EXPECT_NEAR(e.depthRelativeMax, 0.01, 1e-6);
  EXPECT_NEAR(e.depthRelativeMean, 0.01 / 25, 1e-7);
  EXPECT_NEAR(e.normalRadiansMax, 0.1, 1e-6);
  EXPECT_NEAR(e.normalRadiansMean, 0.1 / 25, 1e-7);
}

TEST(ImageError, HolesExtraAndNonFinitePixels) {
  Image candidate = square();
  candidate.patchId[candidate.index(4, 4)] = Image::kNoId;  // a hole: all 8 neighbours covered
  candidate.patchId[candidate.index(2, 2)] = Image::kNoId;  // a silhouette pixel missed: no hole
  candidate.patchId[candidate.index(0, 8)] = 0;             // far from the square: extra
  candidate.depth[candidate.index(0, 8)] = 5.0f;
  candidate.beauty[candidate.index(5, 5)].g = NAN;
  const ImageError e = compareToReference(candidate, square());
  EXPECT_EQ(e.holes, 1u);
  EXPECT_EQ(e.extra, 1u);
  EXPECT_EQ(e.nonFinite, 1u);
  EXPECT_EQ(e.compared, 25u - 3u);
}

TEST(ImageError, BeautyRelativeErrorHasAnAbsoluteFloor) {
  const glm::vec4 black(0.0f), grey(0.5f, 0.5f, 0.5f, 1.0f);
  EXPECT_DOUBLE_EQ(beautyRelativeError(glm::vec4(0.55f, 0.5f, 0.5f, 1.0f), grey, 1e-4), double(0.55f - 0.5f) / 0.5);
  EXPECT_NEAR(beautyRelativeError(glm::vec4(1e-5f, 0.0f, 0.0f, 1.0f), black, 1e-4), 0.1, 1e-6);
  EXPECT_NEAR(beautyFloor(square()), 0.5e-4, 1e-12);
}

TEST(ImageError, ZeroLengthNormalsAreTheWorstAngle) {
  EXPECT_DOUBLE_EQ(normalAngle(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f)), std::numbers::pi);
  EXPECT_NEAR(normalAngle(glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f)), std::numbers::pi / 2, 1e-12);
}

TEST(BlockRelativeRmse, OnePixelBlocksAreTheImageError) {
  Image candidate = square();
  for (std::size_t p = 0; p < candidate.pixelCount(); ++p)
    if (covered(candidate, p)) candidate.beauty[p] += glm::vec4(float(p % 3) * 0.1f, 0.05f, -0.02f, 0.0f);
  EXPECT_NEAR(blockRelativeRmse(candidate, square(), square(), 1), compareToReference(candidate, square()).relativeRmse,
              1e-9);
}

TEST(BlockRelativeRmse, BlocksAverageNoiseAwayAndKeepABias) {
  // +-0.1 alternating from pixel to pixel: noise that a 2 x 2 block cancels;
  // a uniform +0.05 on top is a bias that every block keeps.
  Image noisy = square(), biased = square();
  for (std::size_t p = 0; p < noisy.pixelCount(); ++p) {
    if (!covered(noisy, p)) continue;
    const int x = int(p % 9), y = int(p / 9);
    noisy.beauty[p] += glm::vec4(((x + y) % 2 ? 0.1f : -0.1f) * glm::vec3(1), 0.0f);
    biased.beauty[p] += glm::vec4(0.05f, 0.05f, 0.05f, 0.0f);
  }
  EXPECT_NEAR(blockRelativeRmse(noisy, square(), square(), 1), 0.2, 1e-6);
  EXPECT_NEAR(blockRelativeRmse(biased, square(), square(), 1), 0.1, 1e-6);
  EXPECT_NEAR(blockRelativeRmse(biased, square(), square(), 4), 0.1, 1e-6);
  // The covered 5 x 5 square meets 2 x 2 blocks in whole, half and single
  // blocks: the whole ones cancel, the others keep part of the noise.
  const double blocked = blockRelativeRmse(noisy, square(), square(), 2);
  EXPECT_LT(blocked, 0.2);
  EXPECT_GT(blocked, 0.0);
  // Uncovered pixels never count, whatever they hold.
  Image outside = square();
  outside.beauty[0] = {100.0f, 100.0f, 100.0f, 1.0f};
  EXPECT_EQ(blockRelativeRmse(outside, square(), square(), 3), 0.0);
  EXPECT_EQ(blockRelativeRmse(outside, square(), Image(9, 9), 1), 0.0);
}

TEST(DepthError, ComparesWhereBothAreCoveredAndCountsTheRest) {
  const std::vector<float> reference{10.0f, 10.0f, INFINITY, 20.0f};
  const std::vector<float> candidate{10.0f, INFINITY, 5.0f, 22.0f};
  const DepthError e = compareDepth(candidate, reference);
  EXPECT_EQ(e.bothCovered, 2u);
  EXPECT_EQ(e.coverageMismatch, 2u);
  EXPECT_NEAR(e.maxRelative, 0.1, 1e-7);
  EXPECT_NEAR(e.meanRelative, 0.05, 1e-7);
  EXPECT_TRUE(std::isnan(compareDepth(candidate, {}).meanRelative));
}

TEST(Exposure, PutsTheMeanCoveredRadianceAtMiddleGrey) {
  EXPECT_NEAR(middleGreyExposure(square()), std::log2(0.18 / 0.5), 1e-6);
}

}  // namespace
}  // namespace facet::analysis

// The comparison behind `facet parity`: what passes, what fails, and where
// the failures are counted.
#include <gtest/gtest.h>

#include "analysis/parity.h"

namespace facet::analysis {
namespace {

// A 20x20 image whose centre 10x10 square is covered by a lit surface.
Image square() {
  Image image(20, 20);
  for (int y = 5; y < 15; ++y)
    for (int x = 5; x < 15; ++x) {
      const std::size_t p = image.index(x, y);
      image.beauty[p] = {0.5f, 0.25f, 0.125f, 1.0f};
      image.depth[p] = 10.0f;
      image.shadingNormal[p] = {0.0f, 0.0f, 1.0f};
      image.geometricNormal[p] = {0.0f, 0.0f, 1.0f};
      image.patchId[p] = 0;
      image.faceId[p] = 0;
    }
  return image;
}

const AovParity& aov(const ParityReport& report, const std::string& name) {
  for (const AovParity& a : report.aovs)
    if (a.name == name) return a;
  throw std::invalid_argument(name);
}

TEST(Parity, IdenticalImagesPass) {
  const ParityReport report = compareImages(square(), square());
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_EQ(report.covered, 100u);
  // The ring of pixels on either side of the square's edge.
  EXPECT_EQ(report.silhouettePixels, 12u * 12u - 8u * 8u);
}

TEST(Parity, DepthOverToleranceInTheInteriorFails) {
  Image candidate = square();
  candidate.depth[candidate.index(10, 10)] = 10.0f * (1.0f + 2e-4f);
  const ParityReport report = compareImages(square(), candidate);
  EXPECT_FALSE(report.pass);
  EXPECT_EQ(aov(report, "depth").overInterior, 1u);
  EXPECT_GT(report.heat[candidate.index(10, 10)], 1.0f);
}

TEST(Parity, DepthWithinToleranceAndSilhouetteErrorsPass) {
  Image candidate = square();
  candidate.depth[candidate.index(10, 10)] = 10.0f * (1.0f + 5e-5f);
  candidate.depth[candidate.index(5, 5)] = 11.0f;  // a silhouette pixel
  const ParityReport report = compareImages(square(), candidate);
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_EQ(aov(report, "depth").overSilhouette, 1u);
}

TEST(Parity, NormalAngleIsGated) {
  Image candidate = square();
  candidate.shadingNormal[candidate.index(9, 9)] = {0.002f, 0.0f, 1.0f};
  EXPECT_FALSE(compareImages(square(), candidate).pass);
}

TEST(Parity, BeautyAllowsOneTenthOfAPercentRoundedUpToAPixel) {
  Image candidate = square();
  candidate.beauty[candidate.index(8, 8)].r *= 1.01f;
  EXPECT_TRUE(compareImages(square(), candidate).pass);
  candidate.beauty[candidate.index(9, 8)].g *= 1.01f;
  const ParityReport report = compareImages(square(), candidate);
  EXPECT_FALSE(report.pass);
  EXPECT_EQ(aov(report, "beauty").overInterior, 2u);
}

TEST(Parity, CoverageHoleAwayFromSilhouettesFails) {
  Image candidate = square();
  for (int y = 8; y < 11; ++y)
    for (int x = 8; x < 11; ++x) candidate.patchId[candidate.index(x, y)] = Image::kNoId;
  const ParityReport report = compareImages(square(), candidate);
  EXPECT_FALSE(report.coveragePass);
  EXPECT_EQ(report.coverageMismatches, 9u);
  // Only the centre of the hole has no covered neighbour on the candidate.
  EXPECT_EQ(report.coverageMismatchesInterior, 1u);
  EXPECT_LT(report.heat[candidate.index(9, 9)], 0.0f);
}

TEST(Parity, CoverageDifferingOnOneSilhouettePixelPasses) {
  Image candidate = square();
  candidate.patchId[candidate.index(5, 5)] = Image::kNoId;
  const ParityReport report = compareImages(square(), candidate);
  EXPECT_TRUE(report.coveragePass);
  EXPECT_EQ(report.coverageMismatches, 1u);
}

// The 1e-11-scaled cage: nothing covered is nothing judged, never a pass.
TEST(Parity, AnEmptyImageIsInsufficientCoverageNotAPass) {
  const ParityReport report = compareImages(Image(20, 20), Image(20, 20));
  EXPECT_EQ(report.verdict, Verdict::InsufficientCoverage);
  EXPECT_FALSE(report.pass);
  EXPECT_NE(describe(report).find("parity: INSUFFICIENT COVERAGE: 0 pixels covered on both"), std::string::npos);
  ParityTolerances none;
  none.minCoverage = 0;  // even with no stated minimum
  EXPECT_EQ(compareImages(Image(20, 20), Image(20, 20), none).verdict, Verdict::InsufficientCoverage);
}

// A candidate that renders nothing where the reference has a surface is
// wrong, not unjudged.
TEST(Parity, NothingCoveredAgainstASurfaceIsAFailure) {
  const ParityReport report = compareImages(square(), Image(20, 20));
  EXPECT_EQ(report.verdict, Verdict::Fail);
  EXPECT_FALSE(report.coveragePass);
}

TEST(Parity, FewerCoveredPixelsThanTheMinimumIsInsufficientCoverage) {
  ParityTolerances tolerances;
  tolerances.minCoverage = 101;
  EXPECT_EQ(compareImages(square(), square(), tolerances).verdict, Verdict::InsufficientCoverage);
  tolerances.minCoverage = 100;
  EXPECT_EQ(compareImages(square(), square(), tolerances).verdict, Verdict::Pass);
}

// Two pixels over, where the rule allows one: black pixels off by 3e-5
// pass on the absolute floor (1e-4 of the brightest channel, 0.5), 1e-4 fails.
TEST(Parity, BeautyHasAnAbsoluteFloor) {
  Image reference = square(), candidate = square();
  for (int x : {8, 9}) {
    reference.beauty[reference.index(x, 8)] = {0, 0, 0, 1};
    candidate.beauty[candidate.index(x, 8)] = {3e-5f, 0, 0, 1};
  }
  const ParityReport report = compareImages(reference, candidate);
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_NEAR(aov(report, "beauty").tolerance.absolute, 5e-5, 1e-12);
  for (int x : {8, 9}) candidate.beauty[candidate.index(x, 8)].r = 1e-4f;
  EXPECT_FALSE(compareImages(reference, candidate).pass);
  ParityTolerances looser;
  looser.beautyAbsolute = 2e-4;  // --tolerance beauty=2e-4,1e-3
  EXPECT_TRUE(compareImages(reference, candidate, looser).pass);
}

// |d| <= abs + rel |ref|: depth 10 with abs 1e-3 and rel 1e-4 allows 2e-3.
TEST(Parity, ToleranceIsAnAbsoluteFloorPlusARelativePart) {
  Image candidate = square();
  candidate.depth[candidate.index(10, 10)] = 10.0019f;
  ParityTolerances tolerances;
  tolerances.depth = {1e-3, 1e-4, 1, true};
  EXPECT_TRUE(compareImages(square(), candidate, tolerances).pass);
  candidate.depth[candidate.index(10, 10)] = 10.0021f;
  const ParityReport report = compareImages(square(), candidate, tolerances);
  EXPECT_FALSE(report.pass);
  const WorstPixel& worst = aov(report, "depth").worst.front();
  EXPECT_EQ(worst.x, 10);
  EXPECT_EQ(worst.y, 10);
  EXPECT_NEAR(worst.error, 2.1e-3 / 2e-3, 1e-3);
  EXPECT_EQ(passRule(aov(report, "depth")), "|d| <= 1.0e-03 + 1.0e-04 |ref| on 100% of interior pixels");
}

TEST(Parity, ReportedAovsAreNotGatedAndHaveNoVerdict) {
  Image candidate = square();
  candidate.beauty[candidate.index(10, 10)].a = 0.5f;
  candidate.uv[candidate.index(10, 10)] = {0.5f, 0.5f};
  const ParityReport report = compareImages(square(), candidate);
  EXPECT_TRUE(report.pass);
  for (const char* name : {"alpha", "uv"}) {
    const AovParity& a = aov(report, name);
    EXPECT_FALSE(a.gated);
    EXPECT_EQ(passRule(a), "not gated");
    EXPECT_GT(a.maxAbsolute, 0);
    EXPECT_EQ(a.worst.front().x, 10);
  }
  EXPECT_TRUE(aov(report, "beauty").gated);
}

TEST(Parity, DifferentSizesAreAnError) { EXPECT_THROW(compareImages(Image(2, 2), Image(3, 2)), std::invalid_argument); }

}  // namespace
}  // namespace facet::analysis

#include <gtest/gtest.h>

#include <algorithm>

#include "engine/image/tonemap.h"

namespace facet {
namespace {

constexpr ToneCurve kCurves[] = {ToneCurve::Clamp, ToneCurve::Aces, ToneCurve::PbrNeutral};

TEST(ToneCurves, BlackStaysBlackAndNegativeRadianceIsBlack) {
  for (ToneCurve curve : kCurves) {
    EXPECT_EQ(toneMap(curve, glm::dvec3(0.0)), glm::dvec3(0.0));
    EXPECT_EQ(toneMap(curve, glm::dvec3(-1.0, -0.5, -1e9)), glm::dvec3(0.0));
  }
}

TEST(ToneCurves, GreyRampsRiseMonotonicallyWithinTheDisplayRange) {
  for (ToneCurve curve : kCurves) {
    double previous = 0.0;
    for (double x = 1e-4; x < 1e4; x *= 1.05) {
      const glm::dvec3 out = toneMap(curve, glm::dvec3(x));
      EXPECT_EQ(out.r, out.g) << x;  // grey stays grey
      EXPECT_EQ(out.g, out.b) << x;
      EXPECT_GE(out.r, previous) << "curve " << int(curve) << " at " << x;
      EXPECT_LE(out.r, 1.0);
      previous = out.r;
    }
    EXPECT_GT(previous, 0.98) << "very bright grey reaches white, curve " << int(curve);
  }
}

TEST(ToneCurves, ClampClipsEachChannel) { EXPECT_EQ(clampCurve({0.25, 1.0, 7.0}), glm::dvec3(0.25, 1.0, 1.0)); }

TEST(ToneCurves, AcesIsNarkowiczsRationalFit) {
  const double x = 0.18;
  EXPECT_DOUBLE_EQ(acesCurve(glm::dvec3(x)).r, x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
  EXPECT_LT(acesCurve(glm::dvec3(0.8)).r, 0.8) << "the shoulder compresses before white";
}

TEST(ToneCurves, PbrNeutralLeavesLowValuesUnchangedButForItsToeOffset) {
  // Below the compression start (0.76) and above the toe (0.08) the spec
  // subtracts a constant 0.04: contrast and hue are exactly kept.
  for (const glm::dvec3 c : {glm::dvec3(0.1, 0.3, 0.7), glm::dvec3(0.5), glm::dvec3(0.2, 0.79, 0.12)}) {
    const glm::dvec3 out = pbrNeutralCurve(c);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], c[i] - 0.04, 1e-15) << i;
  }
  // In the toe, x - 6.25 x^2 is subtracted: x = 0.08 meets the constant offset.
  EXPECT_NEAR(pbrNeutralCurve(glm::dvec3(0.08)).r, 0.04, 1e-15);
  EXPECT_NEAR(pbrNeutralCurve(glm::dvec3(0.04)).r, 6.25 * 0.04 * 0.04, 1e-15);
}

TEST(ToneCurves, PbrNeutralDesaturatesHighlightsTowardsWhite) {
  const glm::dvec3 bright = pbrNeutralCurve({20.0, 2.0, 0.5});
  EXPECT_LT(std::max({bright.r, bright.g, bright.b}), 1.0);
  EXPECT_LT(bright.r - bright.b, 0.5) << "much less saturated than the input";
  EXPECT_GT(bright.r, bright.g);
  EXPECT_GT(bright.g, bright.b) << "the hue's order is kept";
}

TEST(ToneCurves, NamesRoundTrip) {
  EXPECT_EQ(toneCurveNamed("clamp"), ToneCurve::Clamp);
  EXPECT_EQ(toneCurveNamed("aces"), ToneCurve::Aces);
  EXPECT_EQ(toneCurveNamed("pbr-neutral"), ToneCurve::PbrNeutral);
  EXPECT_FALSE(toneCurveNamed("filmic"));
  EXPECT_FALSE(toneCurveNamed("ACES"));
}

}  // namespace
}  // namespace facet

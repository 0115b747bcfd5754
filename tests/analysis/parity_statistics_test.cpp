// The paired t-test parity runs on stochastic estimators: renders within
// each other's noise pass, a 5% bias fails, and the distribution it rests on.
#include <gtest/gtest.h>

#include <random>

#include "analysis/parity.h"
#include "analysis/parity_statistics.h"
#include "tests/support/noisy_square.h"

namespace facet::analysis {
namespace {

// 16 pairs of a noisy estimate (10% noise on 0.5), the candidate of each
// pair made from the reference by `candidate`.
PairedRenders pairs(const std::function<Image(const Image&, std::mt19937&)>& candidate) {
  std::mt19937 random(27);
  std::normal_distribution<float> noise(0.5f, 0.05f);
  PairedRenders renders;
  for (int i = 0; i < 16; ++i) {
    const Image reference = testing::noisySquare([&] { return noise(random); });
    renders.add(reference, candidate(reference, random));
  }
  return renders;
}

ParityReport judge(const PairedRenders& renders) {
  return compareImages(renders.referenceMean(), renders.candidateMean(), {}, &renders);
}

TEST(ParityStatistics, EqualRendersPass) {
  const PairedRenders renders = pairs([](const Image& reference, std::mt19937&) { return reference; });
  const ParityReport report = judge(renders);
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_EQ(testing::beautyOf(report).test, "paired t-test");
  EXPECT_EQ(testing::beautyOf(report).renders, 16);
}

// Differences as large as the noise, in either direction: a shadow ray that
// float and double decide differently in some renders.
TEST(ParityStatistics, DifferencesWithinTheNoisePass) {
  auto flips = [](const Image& reference, std::mt19937& random) {
    Image candidate = reference;
    std::normal_distribution<float> disagreement(0.0f, 0.02f);
    for (glm::vec4& b : candidate.beauty)
      if (b.a > 0) b += glm::vec4(disagreement(random), disagreement(random), disagreement(random), 0.0f);
    return candidate;
  };
  const PairedRenders renders = pairs(flips);
  EXPECT_TRUE(judge(renders).pass) << describe(judge(renders));
  // Judged on the means alone, by tolerance, the same renders fail.
  EXPECT_FALSE(compareImages(renders.referenceMean(), renders.candidateMean()).pass);
}

TEST(ParityStatistics, AFivePercentBiasFails) {
  auto biased = [](const Image& reference, std::mt19937&) {
    Image candidate = reference;
    for (glm::vec4& b : candidate.beauty) b = glm::vec4(glm::vec3(b) * 1.05f, b.a);
    return candidate;
  };
  const ParityReport report = judge(pairs(biased));
  EXPECT_EQ(report.verdict, Verdict::Fail);
  EXPECT_GT(testing::beautyOf(report).over(), 90u);
  EXPECT_LT(testing::beautyOf(report).minPValue, testing::beautyOf(report).alpha);
  EXPECT_EQ(testing::beautyOf(report).allowed, 1u);  // 0.25% of 100 pixels, rounded up
}

TEST(ParityStatistics, AConstantOffsetWithNoNoiseInTheDifferenceFails) {
  auto offset = [](const Image& reference, std::mt19937&) {
    Image candidate = reference;
    for (glm::vec4& b : candidate.beauty)
      if (b.a > 0) b.g += 0.01f;
    return candidate;
  };
  EXPECT_FALSE(judge(pairs(offset)).pass);
}

TEST(ParityStatistics, StudentTMatchesTables) {
  EXPECT_DOUBLE_EQ(studentTwoSidedP(0, 5), 1.0);
  EXPECT_NEAR(studentTwoSidedP(2.131, 15), 0.05, 1e-4);
  EXPECT_NEAR(studentTwoSidedP(2.576, 1e7), 0.01, 1e-4);  // the normal distribution
  EXPECT_NEAR(studentTwoSidedP(12.706, 1), 0.05, 1e-4);
  EXPECT_EQ(studentTwoSidedP(INFINITY, 3), 0.0);
}

TEST(ParityStatistics, SidakCorrection) {
  EXPECT_NEAR(sidakAlpha(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(sidakAlpha(0.01, 300), 3.35e-5, 1e-7);
  EXPECT_NEAR(1 - std::pow(1 - sidakAlpha(0.01, 300), 300), 0.01, 1e-12);
}

}  // namespace
}  // namespace facet::analysis

#include "engine/image/sample_rounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace facet {
namespace {

// A round of the whole image: grey `level` plus Gaussian noise of standard
// deviation `sigma` in every channel, and coverage 1.
Image noisyRound(int width, int height, float level, float sigma, std::mt19937& random) {
  Image image(width, height);
  std::normal_distribution<float> noise(0.0f, sigma);
  for (glm::vec4& p : image.beauty) {
    const float v = level + noise(random);
    p = glm::vec4(v, v, v, 1.0f);
  }
  return image;
}

TEST(SampleRounds, CutsTheImageIntoTilesThatCoverItOnce) {
  const TileGrid grid{40, 20, 16};
  EXPECT_EQ(grid.columns(), 3);
  EXPECT_EQ(grid.rows(), 2);
  std::vector<int> covered(40 * 20, 0);
  for (int t = 0; t < grid.count(); ++t) {
    const PixelRect r = grid.tile(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) ++covered[std::size_t(y * 40 + x)];
  }
  for (int c : covered) EXPECT_EQ(c, 1);
  EXPECT_EQ(grid.tile(5), (PixelRect{32, 16, 40, 20}));
}

TEST(SampleRounds, EstimatesTheStandardErrorOfTheMeanFromTheRoundsSpread) {
  std::mt19937 random(7);
  const float level = 0.5f, sigma = 0.1f;
  SampleRounds rounds(32, 16, 16);
  const PixelRect whole = PixelRect::whole(32, 16);
  for (int n = 1; n <= 8; ++n) {
    rounds.add(noisyRound(32, 16, level, sigma, random), whole, {0, 1});
    EXPECT_EQ(rounds.rounds(0), n);
    if (n == 1) {
      EXPECT_TRUE(std::isinf(rounds.error(0))) << "one round says nothing of its spread";
      continue;
    }
    // sigma / sqrt(n) of each pixel's mean, relative to the level; the
    // estimate pools 256 (n - 1) degrees of freedom.
    const double expected = sigma / std::sqrt(double(n)) / level;
    EXPECT_NEAR(rounds.error(0), expected, 0.15 * expected) << n << " rounds";
    EXPECT_NEAR(rounds.error(1), expected, 0.15 * expected) << n << " rounds";
  }
  EXPECT_LT(rounds.error(0), 0.1 / std::sqrt(7.0) / 0.5) << "the error falls as rounds are added";
}

TEST(SampleRounds, AveragesEachPixelOverItsOwnRounds) {
  SampleRounds rounds(32, 16, 16);
  const PixelRect whole = PixelRect::whole(32, 16);
  Image a(32, 16), b(32, 16), c(32, 16);
  for (std::size_t i = 0; i < a.beauty.size(); ++i) {
    a.beauty[i] = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    b.beauty[i] = glm::vec4(3.0f, 0.0f, 0.0f, 0.0f);
    c.beauty[i] = glm::vec4(8.0f, 0.0f, 0.0f, 1.0f);
  }
  rounds.add(a, whole, {0, 1});
  rounds.add(b, whole, {0, 1});
  rounds.add(c, whole, {1});  // tile 0 has stopped
  const std::vector<glm::vec4> beauty = rounds.beauty();
  EXPECT_FLOAT_EQ(beauty[0].r, 2.0f);
  EXPECT_FLOAT_EQ(beauty[0].a, 0.5f);
  EXPECT_FLOAT_EQ(beauty[20].r, 4.0f);
  EXPECT_EQ(rounds.rounds(0), 2);
  EXPECT_EQ(rounds.rounds(1), 3);
}

TEST(SampleRounds, ANoiselessTileHasNoErrorAndDarkTilesAreJudgedAgainstTheFloor) {
  SampleRounds rounds(16, 16, 16);
  const PixelRect whole = PixelRect::whole(16, 16);
  Image dark(16, 16), darker(16, 16);
  for (glm::vec4& p : dark.beauty) p = glm::vec4(0.01f);
  for (glm::vec4& p : darker.beauty) p = glm::vec4(0.0f);
  rounds.add(dark, whole, {0});
  rounds.add(dark, whole, {0});
  EXPECT_EQ(rounds.error(0), 0.0);
  rounds.add(darker, whole, {0});
  // Each pixel: rounds 0.01, 0.01, 0 in luminance; s = 0.01 / sqrt(3), mean's error s / sqrt(3).
  EXPECT_NEAR(rounds.error(0), 0.01 / 3.0 / kLuminanceFloor, 1e-6);
}

// A lamp 100 times white beside a pixel that sees it only in some rounds:
// what the picture shows of that pixel is white or nearly, and it is judged
// by its rounds clipped at white; spread above white is no noise at all.
TEST(SampleRounds, NoiseAboveWhiteIsJudgedAsTheWhiteItShows) {
  SampleRounds rounds(16, 16, 16);
  const PixelRect whole = PixelRect::whole(16, 16);
  Image lamp(16, 16), brighter(16, 16), edge(16, 16);
  for (glm::vec4& p : lamp.beauty) p = glm::vec4(100.0f);
  for (glm::vec4& p : brighter.beauty) p = glm::vec4(120.0f);
  rounds.add(lamp, whole, {0});
  rounds.add(brighter, whole, {0});
  EXPECT_EQ(rounds.error(0), 0.0) << "both rounds show white";
  for (glm::vec4& p : edge.beauty) p = glm::vec4(0.0f);
  rounds.add(edge, whole, {0});
  // Each pixel judged as 1, 1, 0: mean 2/3, s = 1 / sqrt(3), mean's error s / sqrt(3).
  EXPECT_NEAR(rounds.error(0), (1.0 / 3.0) / (2.0 / 3.0), 1e-6);
}

TEST(SampleRounds, RefusesTilesOutsideTheRound) {
  SampleRounds rounds(32, 16, 16);
  Image half(16, 16);
  EXPECT_THROW(rounds.add(half, {0, 0, 16, 16}, {1}), std::invalid_argument);
  EXPECT_THROW(rounds.add(half, {0, 0, 16, 16}, {2}), std::invalid_argument);
  EXPECT_THROW(rounds.add(half, {0, 0, 16, 8}, {0}), std::invalid_argument);
  rounds.add(half, {16, 0, 32, 16}, {1});
  EXPECT_EQ(rounds.rounds(1), 1);
  EXPECT_EQ(rounds.rounds(0), 0);
}

}  // namespace
}  // namespace facet

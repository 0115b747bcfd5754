// The random numbers of path vertices (rules/sampling/path_samples.h): the
// same in float and double, vertex 1 keyed by the scene's seed, and later
// vertices' numbers unrelated to vertex 1's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "rules/rules.h"

namespace facet {
namespace {

namespace f32 = rules::f32;
namespace f64 = rules::f64;

TEST(PathSamples, FloatAndDoubleDrawTheSameNumbers) {
  for (std::uint32_t vertex = 1; vertex <= 8; ++vertex)
    for (std::uint32_t pixel = 0; pixel < 64; ++pixel)
      for (std::uint32_t sample = 0; sample < 5; ++sample) {
        const glm::dvec2 d = f64::path_continuation_u(pixel, sample, 5, 7, vertex);
        const glm::vec2 f = f32::path_continuation_u(pixel, sample, 5, 7, vertex);
        EXPECT_EQ(d.x, double(f.x));
        EXPECT_EQ(d.y, double(f.y));
        EXPECT_EQ(f64::path_roulette_u(pixel, sample, 5, 7, vertex),
                  double(f32::path_roulette_u(pixel, sample, 5, 7, vertex)));
      }
}

TEST(PathSamples, TheFirstVertexKeepsTheScenesSeedAndLaterOnesDrawTheirOwn) {
  EXPECT_EQ(f64::path_vertex_seed(7, 1), 7u);
  for (std::uint32_t vertex = 2; vertex <= 64; ++vertex) {
    EXPECT_NE(f64::path_vertex_seed(7, vertex), 7u);
    EXPECT_NE(f64::path_vertex_seed(7, vertex), f64::path_vertex_seed(7, vertex + 1));
  }
  // Over many pixels, a later vertex's continuation numbers are uncorrelated with vertex 1's.
  const int n = 4096;
  double sumProduct = 0, sumA = 0, sumB = 0;
  for (int pixel = 0; pixel < n; ++pixel) {
    const double a = f64::path_continuation_u(std::uint32_t(pixel), 0, 1, 7, 1).x;
    const double b = f64::path_continuation_u(std::uint32_t(pixel), 0, 1, 7, 2).x;
    sumProduct += a * b;
    sumA += a;
    sumB += b;
  }
  const double covariance = sumProduct / n - (sumA / n) * (sumB / n);
  EXPECT_LT(std::abs(covariance / (1.0 / 12.0)), 4.0 / std::sqrt(double(n)));  // correlation within 4 sigma of 0
}

TEST(PathSamples, RouletteStartsAtTheThirdBounce) {
  const glm::dvec3 dim(0.1, 0.3, 0.2);
  EXPECT_EQ(f64::path_survival_probability(dim, 2), 1.0);
  EXPECT_EQ(f64::path_survival_probability(dim, 3), 0.3);
  EXPECT_EQ(f64::path_survival_probability(glm::dvec3(2.0), 5), 1.0);
}

}  // namespace
}  // namespace facet

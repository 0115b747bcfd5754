// Texture lookups of scenes/texture.h: filters, wrap modes across seams,
// mip levels and the chain.
#include "scenes/texture.h"

#include <gtest/gtest.h>

#include <cmath>

namespace facet::scene {
namespace {

namespace t = rules::f64;

// A 4 x 1 ramp 0, 1, 2, 3 in every channel, one level, linear.
Texture ramp(std::uint32_t wrap) {
  TextureSampler sampler;
  sampler.wrapS = wrap;
  sampler.mipMode = t::FACET_MIP_NONE;
  Texture texture = makeTexture("ramp", 4, 1, 1, {0.0f, 0.25f, 0.5f, 0.75f}, TextureEncoding::Linear, sampler);
  return texture;
}

TEST(TextureSampling, BilinearFilteringInterpolatesBetweenTexelCentres) {
  const Texture texture = ramp(t::FACET_WRAP_CLAMP_TO_EDGE);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.125, 0.5}, 0.0).r, 0.0);   // texel 0's centre
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.25, 0.5}, 0.0).r, 0.125);  // between 0 and 1
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.3125, 0.5}, 0.0).r, 0.1875);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.0, 0.5}, 0.0).r, 0.0);  // clamped edge
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {1.0, 0.5}, 0.0).r, 0.75);
  // Repeat blends the last texel with the first across the seam.
  EXPECT_DOUBLE_EQ(sampleTexture(ramp(t::FACET_WRAP_REPEAT), {0.0, 0.5}, 0.0).r, 0.375);
  EXPECT_DOUBLE_EQ(sampleTexture(ramp(t::FACET_WRAP_REPEAT), {1.25, 0.5}, 0.0).r, 0.125);
  EXPECT_DOUBLE_EQ(sampleTexture(ramp(t::FACET_WRAP_MIRRORED_REPEAT), {-0.125, 0.5}, 0.0).r, 0.0);
}

TEST(TextureSampling, NearestFilteringReadsTheTexelUnderTheCoordinate) {
  Texture texture = ramp(t::FACET_WRAP_REPEAT);
  texture.sampler.magFilter = t::FACET_FILTER_NEAREST;
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.26, 0.5}, 0.0).r, 0.25);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.49, 0.5}, 0.0).r, 0.25);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {-0.01, 0.5}, 0.0).r, 0.75);
  // Minified, the minification filter (linear here) reads level 0.
  EXPECT_DOUBLE_EQ(sampleTexture(texture, {0.25, 0.5}, 1.0).r, 0.125);
}

TEST(TextureSampling, MipLevelsAreChosenFromTheLevelOfDetail) {
  // An 8 x 8 texture whose level l holds the value l, so that a lookup shows
  // which levels it read.
  const Texture built = makeTexture("levels", 8, 8, 1, std::vector<float>(64, 1.0f), TextureEncoding::Linear, {});
  ASSERT_EQ(built.levels.size(), 4u);
  std::vector<TextureLevel> levels(built.levels.begin(), built.levels.end());
  for (std::size_t l = 0; l < levels.size(); ++l)
    for (glm::vec4& texel : levels[l].texels) texel = glm::vec4(float(l));
  Texture texture = built;
  texture.levels = TextureChain(std::move(levels));
  const glm::dvec2 uv(0.3, 0.6);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, -1.0).r, 0.0);  // magnified
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, 1.25).r, 1.25);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, 9.0).r, 3.0);  // the coarsest
  texture.sampler.mipMode = t::FACET_MIP_NEAREST;
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, 1.25).r, 1.0);
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, 1.5).r, 1.0);  // halves round down
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, 1.75).r, 2.0);
  texture.sampler.mipMode = t::FACET_MIP_NONE;
  EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, 2.5).r, 0.0);
}

TEST(TextureSampling, NonFiniteCoordinatesAndLevelsStayInsideTheTexture) {
  const Texture texture = makeTexture("levels", 8, 8, 1, std::vector<float>(64, 0.5f), TextureEncoding::Linear, {});
  const double nan = std::nan(""), huge = 1e30;
  for (const glm::dvec2 uv : {glm::dvec2(nan, 0.5), glm::dvec2(0.5, huge), glm::dvec2(-huge, nan)})
    for (double lod : {nan, 0.0, 3.5, huge}) EXPECT_DOUBLE_EQ(sampleTexture(texture, uv, lod).r, 0.5);
}

TEST(TextureSampling, TheChainAveragesLinearValues) {
  // sRGB 0 and 1 average to linear 0.5, not to sRGB 0.5's 0.214.
  const Texture texture = makeTexture("pair", 2, 1, 3, {0, 0, 0, 1, 1, 1}, TextureEncoding::Srgb, {});
  ASSERT_EQ(texture.levels.size(), 2u);
  EXPECT_FLOAT_EQ(texture.levels[1].texels[0].g, 0.5f);
  EXPECT_EQ(texture.levels[1].width, 1);
}

TEST(TextureSampling, ACopiedTextureSharesItsChain) {
  const Texture texture = makeTexture("pair", 2, 1, 3, {0, 0, 0, 1, 1, 1}, TextureEncoding::Srgb, {});
  const Texture copy = texture;
  EXPECT_TRUE(copy.levels.sameChain(texture.levels));
  EXPECT_EQ(&copy.levels[0].texels[0], &texture.levels[0].texels[0]);
  const Texture again = makeTexture("pair", 2, 1, 3, {0, 0, 0, 1, 1, 1}, TextureEncoding::Srgb, {});
  EXPECT_FALSE(again.levels.sameChain(texture.levels)) << "equal texels, another chain";
}

}  // namespace
}  // namespace facet::scene

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/image/color.h"
#include "engine/image/preview.h"

namespace facet {
namespace {

constexpr int kPictureWidth = 6, kPictureHeight = 5;

int encoded(double linear) { return int(std::lround(linearToSrgb(std::clamp(linear, 0.0, 1.0)) * 255.0)); }

// A surface of colour `surface` on the middle 2 x 3 pixels, its left column
// half covered, the rest missed, as both renderers store it: each pixel the
// mean of its samples, a miss seeing `environment`.
std::vector<glm::vec4> silhouette(glm::vec3 surface, glm::vec3 environment) {
  std::vector<glm::vec4> beauty(kPictureWidth * kPictureHeight, glm::vec4(environment, 0.0f));
  for (int y = 1; y < 4; ++y) {
    beauty[std::size_t(y * kPictureWidth + 2)] = glm::vec4(0.5f * surface + 0.5f * environment, 0.5f);
    beauty[std::size_t(y * kPictureWidth + 3)] = glm::vec4(surface, 1.0f);
  }
  return beauty;
}

PreviewOptions clamped() {
  PreviewOptions options;
  options.curve = ToneCurve::Clamp;
  return options;
}

TEST(Preview, IsOpaqueAndShowsTheEnvironmentByDefault) {
  const glm::vec3 environment(0.2f, 0.3f, 0.4f);
  const std::vector<std::uint8_t> rgba =
      previewPixels(silhouette({0.8f, 0.1f, 0.1f}, environment), kPictureWidth, kPictureHeight, clamped());
  for (std::size_t i = 0; i < rgba.size() / 4; ++i) EXPECT_EQ(rgba[4 * i + 3], 255) << "pixel " << i;
  EXPECT_EQ(rgba[0], encoded(0.2));
  EXPECT_EQ(rgba[1], encoded(0.3));
  EXPECT_EQ(rgba[2], encoded(0.4));
}

TEST(Preview, StraightAlphaKeepsTheSurfaceColourAtItsEdges) {
  const glm::vec3 surface(0.8f, 0.4f, 0.1f);
  PreviewOptions options = clamped();
  options.straightAlpha = true;
  for (const glm::vec3 environment : {glm::vec3(0.0f), glm::vec3(0.6f, 0.5f, 0.9f)}) {
    const std::vector<std::uint8_t> rgba = previewPixels(silhouette(surface, environment), kPictureWidth, kPictureHeight, options);
    for (int y = 1; y < 4; ++y) {
      const std::size_t edge = 4 * std::size_t(y * kPictureWidth + 2), inside = edge + 4;
      EXPECT_EQ(rgba[edge + 3], 128);
      EXPECT_EQ(rgba[inside + 3], 255);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(rgba[edge + c], encoded(surface[c]), 1) << "no darkened or tinted edge, channel " << c;
        EXPECT_EQ(rgba[inside + c], encoded(surface[c]));
      }
    }
    EXPECT_EQ(rgba[3], 0) << "a miss is transparent";
  }
}

TEST(Preview, ABackgroundReplacesTheEnvironmentBehindTheEdges) {
  const glm::vec3 surface(0.8f, 0.4f, 0.1f), background(0.0f, 1.0f, 0.0f);
  PreviewOptions options = clamped();
  options.background = background;
  const std::vector<std::uint8_t> rgba =
      previewPixels(silhouette(surface, {0.6f, 0.5f, 0.9f}), kPictureWidth, kPictureHeight, options);
  const std::size_t edge = 4 * std::size_t(2 * kPictureWidth + 2);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(rgba[c], encoded(background[c]));
    EXPECT_NEAR(rgba[edge + c], encoded(0.5 * surface[c] + 0.5 * background[c]), 1) << c;
  }
  EXPECT_EQ(rgba[edge + 3], 255);
}

TEST(Preview, ExposureScalesByPowersOfTwoBeforeTheCurve) {
  PreviewOptions options = clamped();
  options.exposure = 2.0f;
  const std::vector<std::uint8_t> rgba = previewPixels({glm::vec4(0.1f, 0.2f, 0.3f, 1.0f)}, 1, 1, options);
  EXPECT_EQ(rgba[0], encoded(0.4));
  EXPECT_EQ(rgba[1], encoded(0.8));
  EXPECT_EQ(rgba[2], 255);
}

}  // namespace
}  // namespace facet

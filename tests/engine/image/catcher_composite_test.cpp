// The shadow catcher's composite on hand-made planes: the model's pixels
// are left as rendered, the unshadowed ground is the background, the
// shadowed ground darkens it by the ratio, summed over a window of the
// ground's pixels, a silhouette pixel blends by its coverage, and a ground no
// light reaches is no shadow.
#include "engine/image/catcher_composite.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace facet {
namespace {

using Plane = std::vector<glm::vec4>;

void expectNear(const glm::vec4& got, const glm::vec4& want, const char* what) {
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-6f) << what << ", channel " << c;
}

const glm::vec4 kBackground{0.2f, 0.3f, 0.4f, 0.0f};
const glm::vec4 kGround{0.5f, 0.6f, 0.7f, 1.0f};  // unshadowed, as the ground alone sees it

TEST(CatcherComposite, LeavesTheModelsPixelsAsRendered) {
  const Plane model{{0.9f, 0.1f, 0.1f, 1.0f}};
  const Plane out = catchShadows(1, 1, model, Plane{{0.0f, 0.0f, 0.0f, 1.0f}}, Plane{kGround});
  expectNear(out[0], model[0], "a covered pixel");
}

TEST(CatcherComposite, TheUnshadowedGroundIsTheBackground) {
  const Plane out = catchShadows(1, 1, Plane{kBackground}, Plane{kGround}, Plane{kGround});
  expectNear(out[0], kBackground, "unshadowed ground");
}

TEST(CatcherComposite, TheShadowedGroundDarkensTheBackgroundByTheRatio) {
  const Plane out =
      catchShadows(1, 1, Plane{kBackground}, Plane{glm::vec4(0.25f * glm::vec3(kGround), 1.0f)}, Plane{kGround});
  expectNear(out[0], glm::vec4(0.25f * glm::vec3(kBackground), 0.0f), "a quarter of the light");
  // Per channel: light of one colour blocked leaves the others.
  const Plane coloured =
      catchShadows(1, 1, Plane{kBackground}, Plane{{kGround.r, 0.5f * kGround.g, 0.0f, 1.0f}}, Plane{kGround});
  expectNear(coloured[0], {kBackground.r, 0.5f * kBackground.g, 0.0f, 0.0f}, "per channel");
}

TEST(CatcherComposite, ClampsTheRatioToOne) {
  const Plane out =
      catchShadows(1, 1, Plane{kBackground}, Plane{glm::vec4(2.0f * glm::vec3(kGround), 1.0f)}, Plane{kGround});
  expectNear(out[0], kBackground, "no ground is brighter than the background");
}

TEST(CatcherComposite, ASilhouettePixelBlendsByCoverage) {
  // The middle pixel: half model (colour C), half ground in a shadow that
  // lets a fifth of the light through; its neighbours see the background.
  const glm::vec3 c{0.9f, 0.8f, 0.1f};
  Plane model(9, kBackground), holdout(9, glm::vec4(0.2f * glm::vec3(kGround), 1.0f)), ground(9, kGround);
  model[4] = glm::vec4(0.5f * c + 0.5f * glm::vec3(kBackground), 0.5f);
  holdout[4] = glm::vec4(0.5f * 0.2f * glm::vec3(kGround), 1.0f);  // the black model and the shadowed ground
  const Plane out = catchShadows(3, 3, model, holdout, ground);
  expectNear(out[4], glm::vec4(0.5f * c + 0.5f * 0.2f * glm::vec3(kBackground), 0.5f), "half model, half shadow");
  expectNear(out[0], glm::vec4(0.2f * glm::vec3(kBackground), 0.0f), "a neighbour in the shadow");
}

TEST(CatcherComposite, APixelWithoutGroundIsLeftAlone) {
  // The holdout covers what the model covers: no ground behind the pixel.
  const Plane model{{0.3f, 0.3f, 0.3f, 0.5f}};
  const Plane out = catchShadows(1, 1, model, Plane{{0.0f, 0.0f, 0.0f, 0.5f}}, Plane{kGround});
  expectNear(out[0], model[0], "no ground share");
  // Nor does a pixel whose ground is past the edge of the image's others.
  const Plane alone = catchShadows(1, 1, Plane{kBackground}, Plane{kBackground}, Plane{kBackground});
  expectNear(alone[0], kBackground, "neither model nor ground");
}

TEST(CatcherComposite, AGroundNoLightReachesCastsNoShadow) {
  const Plane out =
      catchShadows(1, 1, Plane{kBackground}, Plane{{0.0f, 0.0f, 0.0f, 1.0f}}, Plane{{0.0f, 0.0f, 0.0f, 1.0f}});
  expectNear(out[0], kBackground, "unlit ground");
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(out[0][c]));
}

TEST(CatcherComposite, SumsTheRatioOverTheWindowsGround) {
  // Every other pixel shadowed outright: a noisy visibility, whose window
  // holds 13 lit pixels of 25.
  Plane holdout(25, kGround);
  for (std::size_t i = 1; i < 25; i += 2) holdout[i] = {0.0f, 0.0f, 0.0f, 1.0f};
  const Plane model(25, kBackground), ground(25, kGround);
  expectNear(catchShadows(5, 5, model, holdout, ground, 2)[12], glm::vec4(0.52f * glm::vec3(kBackground), 0.0f),
             "the window's ratio");
  expectNear(catchShadows(5, 5, model, holdout, ground, 0)[12], kBackground, "a pixel's own ratio");
  // The model's pixels hold no ground: the black holdout there is no shadow.
  const glm::vec4 covered{0.9f, 0.1f, 0.1f, 1.0f}, half(0.5f * glm::vec3(kGround), 1.0f);
  const Plane row = catchShadows(3, 1, Plane{covered, kBackground, kBackground},
                                 Plane{{0.0f, 0.0f, 0.0f, 1.0f}, half, half}, Plane(3, kGround), 1);
  expectNear(row[1], glm::vec4(0.5f * glm::vec3(kBackground), 0.0f), "beside the model");
}

TEST(CatcherComposite, RejectsPlanesOfOtherSizes) {
  EXPECT_THROW(catchShadows(2, 1, Plane(2, kBackground), Plane(1, kGround), Plane(2, kGround)), std::invalid_argument);
}

}  // namespace
}  // namespace facet

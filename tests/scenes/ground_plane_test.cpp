// The preview's ground: where it stands and how its scenes are lit.
#include "scenes/ground_plane.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/support/ground_blob.h"

namespace facet::scene {
namespace {

TEST(GroundPlane, TouchesTheLowestPointOfTheLimitSurface) {
  const Scene model = facet::testing::blobOverGround();
  const SceneGeometry geometry = buildGeometry(model);
  const double lowest = lowestPoint(geometry);
  EXPECT_GE(lowest, geometry.bounds.lo.y) << "the patches' hulls hold the surface";
  EXPECT_LT(lowest, geometry.bounds.lo.y + 0.01 * geometry.bounds.diagonal());
  const GroundScenes scenes = groundScenes(model);
  ASSERT_EQ(scenes.ground.objects.size(), 1u);
  for (const glm::dvec3& p : scenes.ground.objects[0].cage.positions) EXPECT_DOUBLE_EQ(p.y, lowest);
  ASSERT_EQ(scenes.holdout.objects.size(), 2u);
  EXPECT_EQ(scenes.holdout.objects[0].cage.positions, model.objects[0].cage.positions);
  EXPECT_EQ(scenes.holdout.objects[1].cage.positions, scenes.ground.objects[0].cage.positions);
}

TEST(GroundPlane, IsLitWithShadowRays) {
  Scene model = facet::testing::blobOverGround();
  model.environment->occlusion = false;
  const GroundScenes prefiltered = groundScenes(model);
  EXPECT_EQ(prefiltered.ground.environment->method, IblMethod::Filtered);
  EXPECT_EQ(prefiltered.holdout.environment->method, IblMethod::Filtered);
  EXPECT_TRUE(prefiltered.holdout.environment->occlusion);
  // The ground alone has nothing to block its light: its shadow rays could
  // only pass, so it casts none and draws the same samples.
  EXPECT_FALSE(prefiltered.ground.environment->occlusion);
  model.environment->method = IblMethod::Sampled;
  EXPECT_EQ(groundScenes(model).holdout.environment->method, IblMethod::Sampled);
  const materials::Material& holdout =
      prefiltered.holdout.materials[std::size_t(prefiltered.holdout.objects[0].material)];
  EXPECT_EQ(holdout.diffuse, glm::dvec3(0.0));
  EXPECT_EQ(holdout.fresnel, rules::f64::F_DIELECTRIC);
  EXPECT_EQ(holdout.eta, glm::dvec3(1.0)) << "no interface: it reflects nothing";
  model.environment.reset();
  EXPECT_THROW(groundScenes(model), std::invalid_argument);
}

}  // namespace
}  // namespace facet::scene

// How an object's refinement is chosen for the camera that sees it.
#include "scenes/scene_geometry.h"
#include "tests/support/cages.h"

#include <gtest/gtest.h>

#include <cmath>

namespace facet::scene {
namespace {

using testing::singleFace;

// Flat polygons are diced once; a twisted quad as finely as its twist asks.
TEST(SceneGeometry, DicingFollowsTheTwistOutOfPlane) {
  Object object;
  object.subdivision = Subdivision::None;
  object.cage = singleFace({{0, 0, 0}, {1, 0, 0}, {1.5, 1, 0}, {0, 1, 0}});  // planar, not a parallelogram
  Camera camera;
  camera.eye = {0.5, 0.5, 4};
  camera.target = {0.5, 0.5, 0};
  RenderSettings settings;
  settings.height = 512;
  const RefinementChoice flat = chooseRefinement(object, camera, settings);
  EXPECT_EQ(flat.isolationLevel, 0);
  EXPECT_LT(flat.twistPixels, 1e-9);
  EXPECT_EQ(flat.tessellationRate, 1);

  object.cage.positions[2].z = 0.2;
  const RefinementChoice twisted = chooseRefinement(object, camera, settings);
  EXPECT_GT(twisted.twistPixels, 1.0);
  EXPECT_EQ(twisted.tessellationRate, int(std::ceil(std::sqrt(twisted.twistPixels / (4 * settings.pixelTolerance)))));
  EXPECT_GT(twisted.tessellationRate, 1);

  object.subdivision = Subdivision::CatmullClark;
  EXPECT_GE(chooseRefinement(object, camera, settings).isolationLevel, 1);
}

}  // namespace
}  // namespace facet::scene

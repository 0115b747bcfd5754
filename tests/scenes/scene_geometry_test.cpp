// How an object's refinement is chosen for the camera that sees it.
#include "scenes/scene_geometry.h"
#include "scenes/input_error.h"
#include "tests/support/cages.h"

#include <gmock/gmock.h>
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

// Beyond 1e100 the products refinement takes of coordinate differences
// would overflow double.
TEST(SceneGeometry, CoordinatesBeyond1e100AreRefused) {
  Object object;
  object.name = "far";
  object.cage = singleFace({{0, 0, 0}, {1e308, 0, 0}, {1e308, 1e308, 0}, {0, 1e308, 1e-300}});
  object.cage.source = "far.obj";
  RenderSettings settings;
  try {
    chooseRefinement(object, Camera{}, settings);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("far.obj: cage coordinates must lie within +-1e100: object 'far': vertex 2 is at 1e+308"));
  }
  object.cage = singleFace({{0, 0, 0}, {1e100, 0, 0}, {1e100, 1e100, 0}, {0, 1e100, 1e99}});
  const RefinementChoice choice = chooseRefinement(object, Camera{}, settings);
  EXPECT_TRUE(std::isfinite(choice.edgePixels));
  EXPECT_GE(choice.isolationLevel, 1);
}

}  // namespace
}  // namespace facet::scene

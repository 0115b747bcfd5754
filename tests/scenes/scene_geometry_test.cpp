// How an object's refinement is chosen for the camera that sees it.
#include "scenes/scene_geometry.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/cages.h"
#include "tests/support/scoped_env.h"

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

// An n x n grid of unit quads in z = 0, or of two triangles a cell.
ControlCage grid(int n, bool triangles) {
  ControlCage cage;
  cage.source = "grid.obj";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) cage.positions.push_back({i, j, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = b + n + 1, d = a + n + 1;
      if (triangles) {
        cage.faceVertexCounts.insert(cage.faceVertexCounts.end(), {3, 3});
        cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), {a, b, c, a, c, d});
      } else {
        cage.faceVertexCounts.push_back(4);
        cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), {a, b, c, d});
      }
    }
  return cage;
}

Scene gridScene(int n, bool triangles) {
  Scene scene;
  scene.materials.push_back(defaultMaterial());
  Object object;
  object.name = "grid";
  object.cage = grid(n, triangles);
  scene.objects.push_back(object);
  scene.camera.eye = {0.5 * n, 0.5 * n, 2.0 * n};
  scene.camera.target = {0.5 * n, 0.5 * n, 0};
  scene.render.width = scene.render.height = 8;
  return scene;
}

// A cage whose quads alone would need more than the memory limit to refine
// is refused before any is refined (a triangle is three quads).
TEST(SceneGeometry, CagesWhoseRefinementCannotFitInMemoryAreRefused) {
  const facet::testing::ScopedEnv limit("FACET_MEMORY_LIMIT", "64");
  EXPECT_GE(buildGeometry(gridScene(100, false)).patchCount(), 100 * 100);
  for (bool triangles : {false, true}) {
    const int n = triangles ? 106 : 260;  // 67,416 and 67,600 quads: over 64 MiB at 1 KB a quad
    try {
      buildGeometry(gridScene(n, triangles));
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::StartsWith("grid.obj: the scene's cages must fit in memory once refined: "
                                                  "object 'grid' brings the scene's cages to " +
                                                  std::to_string(triangles ? 6 * n * n : n * n) + " quads"));
      EXPECT_THAT(e.what(), ::testing::HasSubstr("the limit is 0.1 GB (FACET_MEMORY_LIMIT); decimate the mesh"));
    }
  }
}

}  // namespace
}  // namespace facet::scene

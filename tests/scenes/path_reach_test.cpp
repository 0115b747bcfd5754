// Where no continuation can hit (scenes/path_reach.h): one closed convex
// object seen from outside, on what the exact method ray casts, and nothing
// else: concave surfaces, open ones, an eye inside, glass, two objects.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "scenes/obj_cage.h"
#include "scenes/path_reach.h"
#include "scenes/scene_geometry.h"
#include "tests/support/blob_scene.h"
#include "tests/support/cages.h"
#include "tests/support/inside_sphere.h"

namespace facet::scene {
namespace {

Scene lone(ControlCage cage, Subdivision subdivision = Subdivision::CatmullClark) {
  Scene s;
  s.materials.push_back(facet::testing::lambertian(0.5));
  Object object;
  object.name = cage.source;
  object.cage = std::move(cage);
  object.subdivision = subdivision;
  s.objects.push_back(std::move(object));
  s.camera.eye = {1.5, 1.0, 5.5};
  s.render.width = s.render.height = 64;
  s.render.bounces = 8;
  return s;
}

ControlCage cage(const std::filesystem::path& path) { return loadObjCage(path); }
ControlCage cubeCage() { return cage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj"); }

// The decision, and the measurement behind it.
PathReach decide(const Scene& s, const char* label) {
  const SceneGeometry geometry = buildGeometry(s);
  const ObjectGeometry& g = geometry.objects.front();
  const ConvexityCheck check = checkConvexity(g.surface, g.bvh, s.camera.eye);
  std::printf("%-22s closed sphere %d, %d patches, %zu samples, excess %.3g, eye clearance %.3g diagonals\n", label,
              int(closesIntoSphere(s.objects.front().cage)), g.surface.patchCount(), check.samples, check.excess,
              check.eyeClearance);
  return pathReach(s, geometry);
}

TEST(PathReach, TheCubeCagesLimitSurfaceIsConvex) {
  const PathReach reach = decide(lone(cubeCage()), "cube, Catmull-Clark");
  ASSERT_FALSE(reach.continues);
  EXPECT_EQ(reach.why, "one convex closed object, seen from outside; no continuation can hit");
}

TEST(PathReach, AUvSphereAsAuthoredIsConvex) {
  EXPECT_FALSE(decide(lone(facet::testing::uvSphereCage(32, 64), Subdivision::None), "uv sphere as authored").continues);
}

TEST(PathReach, FromInsideAConvexSphereContinuationsHit) {
  Scene s = lone(facet::testing::uvSphereCage(32, 64), Subdivision::None);
  s.camera.eye = {0.0, 0.0, 0.0};
  s.camera.target = {0.0, 0.0, -1.0};
  EXPECT_TRUE(decide(s, "uv sphere, eye inside").continues);
}

TEST(PathReach, ATorusBounces) {
  const Scene s = lone(testing::torusCage(12, 8, 1.0, 0.35));
  EXPECT_TRUE(closesIntoSphere(s.objects.front().cage) == false);  // genus 1
  EXPECT_TRUE(decide(s, "torus").continues);
  // Its limit surface is concave, whatever its topology says.
  const SceneGeometry geometry = buildGeometry(s);
  EXPECT_GT(checkConvexity(geometry.objects[0].surface, geometry.objects[0].bvh, s.camera.eye).excess, 0.05);
}

TEST(PathReach, TheTeacupBounces) {
  EXPECT_TRUE(decide(lone(cage(std::filesystem::path(FACET_CAGE_DIR) / "newell_teacup.obj")), "teacup").continues);
}

// A peanut: a box of three sections along x whose waist is pinched to
// `waist` of its ends, closed with one quad at each end.
ControlCage peanutCage(double waist) {
  ControlCage cage;
  cage.source = "peanut";
  for (int ring = 0; ring < 4; ++ring) {
    const double scale = ring == 1 || ring == 2 ? waist : 1.0;
    for (auto [y, z] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      cage.positions.push_back({-3.0 + 2.0 * ring, scale * y, scale * z});
  }
  auto face = [&](std::initializer_list<int> vertices) {
    cage.faceVertexCounts.push_back(int(vertices.size()));
    cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), vertices);
  };
  face({0, 3, 2, 1});
  face({12, 13, 14, 15});
  for (int ring = 0; ring < 3; ++ring)
    for (int k = 0; k < 4; ++k)
      face({4 * ring + k, 4 * ring + (k + 1) % 4, 4 * (ring + 1) + (k + 1) % 4, 4 * (ring + 1) + k});
  return cage;
}

TEST(PathReach, AClosedConcaveSurfaceBounces) {
  Scene s = lone(peanutCage(0.4));
  s.camera.eye = {2.0, 3.0, 12.0};
  EXPECT_TRUE(closesIntoSphere(s.objects.front().cage));
  EXPECT_TRUE(decide(s, "peanut").continues);
  // Unpinched, the same cage is a convex box.
  Scene box = lone(peanutCage(1.0));
  box.camera.eye = s.camera.eye;
  EXPECT_FALSE(decide(box, "peanut, unpinched").continues);
}

// The preview's two shapes (scenes/examples/preview.json), each on its own:
// the superball's limit is convex, the creased box's is not.
TEST(PathReach, ThePreviewsSuperballAndCreasedBox) {
  const Scene ball = lone(cage(std::filesystem::path(FACET_EXAMPLES_DIR) / "superball.obj"));
  const Scene box = lone(cage(std::filesystem::path(FACET_CAGE_DIR) / "creased_box.obj"));
  const bool ballConvex = !decide(ball, "superball").continues;
  const bool boxConvex = !decide(box, "creased box").continues;
  std::printf("superball: %s; creased box: %s\n", ballConvex ? "none cast" : "traced",
              boxConvex ? "none cast" : "traced");
  EXPECT_TRUE(ballConvex);
  // Where its semi-sharp crease stops halfway along an edge, the creased box's limit is a saddle.
  EXPECT_FALSE(boxConvex);
}

TEST(PathReach, AnythingElseTraces) {
  Scene open = lone(cubeCage());
  open.objects.front().cage.holes = {0};
  EXPECT_TRUE(decide(open, "cube with a hole").continues);

  Scene glass = lone(cubeCage());
  glass.materials.front().transmission = 1.0;
  glass.materials.front().name = "glass";
  EXPECT_EQ(pathReach(glass, buildGeometry(glass)).why, "'glass' transmits");

  Scene two = lone(cubeCage());
  two.objects.push_back(two.objects.front());
  for (glm::dvec3& p : two.objects.back().cage.positions) p.x += 3.0;
  EXPECT_EQ(pathReach(two, buildGeometry(two)).why, "2 objects can see each other");

  Scene tessellated = lone(cubeCage());
  tessellated.render.method = IntersectionMethod::Tessellated;
  EXPECT_TRUE(pathReach(tessellated, buildGeometry(tessellated)).continues);
}

}  // namespace
}  // namespace facet::scene

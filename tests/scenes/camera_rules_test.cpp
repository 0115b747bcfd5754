// The one rule a camera meets, wherever it comes from.
#include "scenes/camera_rules.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace facet::scene {
namespace {

std::string problemOf(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up) {
  Camera camera;
  camera.eye = eye;
  camera.target = target;
  camera.up = up;
  const char* problem = cameraProblem(camera);
  return problem ? problem : "";
}

TEST(CameraRules, ACameraNeedsAViewDirectionAndAnUpAcrossIt) {
  EXPECT_EQ(problemOf({0, 0, 5}, {0, 0, 0}, {0, 1, 0}), "");
  EXPECT_EQ(problemOf({1e-3, 0, 0}, {0, 0, 0}, {0, 0, 1e-6}), "") << "small but well-defined";
  EXPECT_EQ(problemOf({1, 2, 3}, {1, 2, 3}, {0, 1, 0}), "eye and target must differ");
  EXPECT_EQ(problemOf({-1e308, 0, 0}, {1e308, 0, 0}, {0, 1, 0}), "eye and target are too far apart (or not finite)");
  EXPECT_EQ(problemOf({0, 0, NAN}, {0, 0, 0}, {0, 1, 0}), "eye and target are too far apart (or not finite)");
  EXPECT_EQ(problemOf({0, 0, 5}, {0, 0, 0}, {0, 0, 0}), "up must not be zero or parallel to the view direction");
  EXPECT_EQ(problemOf({0, 0, 5}, {0, 0, 0}, {0, 0, -2}), "up must not be zero or parallel to the view direction");
  EXPECT_EQ(problemOf({0, 0, 5}, {0, 0, 0}, {0, NAN, 1}), "up must not be zero or parallel to the view direction");
}

}  // namespace
}  // namespace facet::scene

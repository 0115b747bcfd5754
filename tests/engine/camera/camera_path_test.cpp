// Frames' cameras: keys interpolated and held.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "engine/camera/camera_path.h"

namespace facet::camera {
namespace {

scene::CameraKey key(int frame, glm::dvec3 eye, double fov) {
  scene::CameraKey k;
  k.frame = frame;
  k.camera.eye = eye;
  k.camera.verticalFovDegrees = fov;
  return k;
}

TEST(CameraPath, KeysAreLinearBetweenAndHeldOutside) {
  const std::vector<scene::CameraKey> keys = {key(0, {0, 0, 4}, 30), key(10, {10, 0, 4}, 50), key(20, {10, 0, 4}, 50)};
  EXPECT_EQ(keyedCamera(keys, 5).eye, glm::dvec3(5, 0, 4));
  EXPECT_DOUBLE_EQ(keyedCamera(keys, 5).verticalFovDegrees, 40);
  EXPECT_EQ(keyedCamera(keys, 10).eye, glm::dvec3(10, 0, 4));
  EXPECT_EQ(keyedCamera(keys, -3).eye, glm::dvec3(0, 0, 4));
  EXPECT_EQ(keyedCamera(keys, 99).eye, glm::dvec3(10, 0, 4));
}

TEST(CameraPath, KeysFurtherApartThanAnIntHoldsInterpolate) {
  const std::vector<scene::CameraKey> keys = {key(-2000000000, {0, 0, 4}, 30), key(2000000000, {8, 0, 4}, 50)};
  EXPECT_EQ(keyedCamera(keys, 0).eye, glm::dvec3(4, 0, 4));
  EXPECT_DOUBLE_EQ(keyedCamera(keys, 1000000000).verticalFovDegrees, 45);
}

}  // namespace
}  // namespace facet::camera

// Frames' cameras: keys interpolated and held, and the turntable's orbit.
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

TEST(CameraPath, TheTurntableOrbitsTheTargetAboutUp) {
  scene::Camera c;
  c.eye = {1, 2, 5};
  c.target = {1, 0, 0};
  const double distance = glm::length(c.eye - c.target);
  for (int f = 0; f < 8; ++f) {
    const scene::Camera turned = turntableCamera(c, f, 8);
    EXPECT_NEAR(glm::length(turned.eye - turned.target), distance, 1e-12);
    EXPECT_NEAR(turned.eye.y, 2, 1e-12) << "the eye keeps its height along up";
    EXPECT_EQ(turned.target, c.target);
  }
  EXPECT_EQ(turntableCamera(c, 0, 8).eye, c.eye);
  const glm::dvec3 quarter = turntableCamera(c, 2, 8).eye, half = turntableCamera(c, 4, 8).eye;
  EXPECT_NEAR(quarter.x, 6, 1e-12);  // a right-handed turn about +y takes +z to +x
  EXPECT_NEAR(quarter.z, 0, 1e-12);
  EXPECT_NEAR(half.z, -5, 1e-12);
  EXPECT_NEAR(half.x, 1, 1e-12);
}

}  // namespace
}  // namespace facet::camera

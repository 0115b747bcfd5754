// worldToCamera and worldToNDC in OpenEXR's conventions: a point on the ray
// through a pixel's centre lands at that centre in NDC, in front of the
// camera, with +x right and +y up; and faceIds map to their objects.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>

#include "engine/camera/camera.h"
#include "engine/image/exr_metadata.h"
#include "engine/image/image.h"

namespace facet {
namespace {

using Vector = std::array<double, 4>;

// Imath's convention: the point is a row vector on the left.
Vector times(const Vector& p, const RowMatrix& m) {
  Vector q{};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) q[j] += p[i] * m[i][j];
  return q;
}

ExrCamera exrCamera(const rules::f64::CameraFrame& f) { return {f.eye, f.right, f.up, f.forward, f.tanHalfFovY, f.aspect}; }

TEST(ExrCameraMatrices, APointOnAPixelsRayLandsAtThatPixelsCentre) {
  scene::Camera camera;
  camera.eye = {3.0, -1.0, 7.0};
  camera.target = {-0.5, 0.25, 1.0};
  camera.up = {0.1, 1.0, 0.0};
  camera.verticalFovDegrees = 47.0;
  const int width = 37, height = 23;
  const rules::f64::CameraFrame frame = camera::cameraFrame(camera, width, height);
  const RowMatrix toCamera = worldToCamera(exrCamera(frame)), toNdc = worldToNdc(exrCamera(frame));
  for (const auto& [px, py] : {std::pair{0, 0}, {36, 0}, {0, 22}, {36, 22}, {20, 8}, {5, 17}})
    for (const double distance : {0.5, 3.0, 40.0}) {
      const double x = px + 0.5, y = py + 0.5;
      const glm::dvec3 p = frame.eye + distance * rules::f64::camera_ray_direction(frame, x, y, width, height);
      const Vector ndc = times({p.x, p.y, p.z, 1.0}, toNdc);
      EXPECT_NEAR(ndc[0] / ndc[3], x / width, 1e-12) << px << ',' << py;
      EXPECT_NEAR(ndc[1] / ndc[3], y / height, 1e-12) << px << ',' << py;
      const Vector c = times({p.x, p.y, p.z, 1.0}, toCamera);
      EXPECT_NEAR(std::hypot(c[0], c[1], c[2]), distance, 1e-12) << "a rigid motion with the eye at the origin";
      EXPECT_GT(c[2], 0.0) << "in front of the camera: +z";
      EXPECT_EQ(c[0] > 0.0, x > 0.5 * width) << "+x to the right";
      EXPECT_EQ(c[1] > 0.0, y < 0.5 * height) << "+y up";
      EXPECT_NEAR(ndc[2] / ndc[3], 1.0 / c[2], 1e-12);
    }
}

TEST(ExrCameraMatrices, CameraSpaceIsLeftHandedLikeOpenExrs) {
  const rules::f64::CameraFrame frame = camera::cameraFrame(scene::Camera{}, 4, 4);
  const RowMatrix m = worldToCamera(exrCamera(frame));
  const glm::dvec3 x{m[0][0], m[1][0], m[2][0]}, y{m[0][1], m[1][1], m[2][1]}, z{m[0][2], m[1][2], m[2][2]};
  // The camera's axes in a right-handed world: x cross y is -z.
  EXPECT_NEAR(glm::length(glm::cross(x, y) + z), 0.0, 1e-15);
}

TEST(ObjectOfFace, FacesBelongToTheObjectThatNumbersThem) {
  const ExrNames names{{"a", "b", "c"}, {0, 4, 4}, {0, 0, 0}, {"m"}};  // b has no faces
  EXPECT_EQ(objectOfFace(names, 0), 0u);
  EXPECT_EQ(objectOfFace(names, 3), 0u);
  EXPECT_EQ(objectOfFace(names, 4), 2u);
  EXPECT_EQ(objectOfFace(names, 900), 2u);
  EXPECT_EQ(objectOfFace(names, Image::kNoId), Image::kNoId);
}

}  // namespace
}  // namespace facet

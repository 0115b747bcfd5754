// The CPU reference against closed-form answers of the course's lighting
// model, and its AOVs against each other.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine/camera/camera.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/renderer.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "scenes/environment_map.h"
#include "tests/support/blob_scene.h"
#include "tests/support/scoped_env.h"

namespace facet {
namespace {

using scene::Light;
using scene::LightType;

// A flat 3x3-quad cage in the plane y = height, facing +y; its limit
// surface is flat too.
scene::ControlCage plane(double height, double halfSize) {
  std::ostringstream obj;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      obj << "v " << (i / 1.5 - 1) * halfSize << " " << height << " " << (j / 1.5 - 1) * halfSize << "\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = 4 * j + i + 1;
      obj << "f " << a << " " << a + 4 << " " << a + 5 << " " << a + 1 << "\n";
    }
  return scene::parseObjCage(obj.str(), "plane");
}

// White Lambert (c_diff = 1, F(0) = 0) ground seen from straight above, at
// an odd resolution so that the centre pixel's ray is the optical axis.
scene::Scene groundScene(scene::IntersectionMethod method) {
  scene::Scene s;
  materials::Material white = scene::defaultMaterial();
  white.diffuse = glm::dvec3(1.0);
  white.f0 = glm::dvec3(0.0);
  s.materials.push_back(white);
  scene::Object ground;
  ground.name = "ground";
  ground.cage = plane(0.0, 4.0);
  s.objects.push_back(std::move(ground));
  s.camera.eye = {0, 5, 0};
  s.camera.target = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.camera.verticalFovDegrees = 30;
  s.render.width = s.render.height = 9;
  s.render.method = method;
  return s;
}

glm::vec4 centre(const Image& image) { return image.beauty[image.index(image.width / 2, image.height / 2)]; }

class ReferenceRenderer : public ::testing::TestWithParam<scene::IntersectionMethod> {};

// L_o = π (c_diff / π) c_light (n·l) = c_light for a white surface lit head-on.
TEST_P(ReferenceRenderer, WhiteLambertLitHeadOnReturnsCLight) {
  scene::Scene s = groundScene(GetParam());
  s.lights.push_back({LightType::Directional, glm::dvec3(0.25, 0.5, 1.0), {}, {0, -1, 0}});
  const glm::vec4 c = centre(render(s, Backend::Cpu).image);
  EXPECT_NEAR(c.r, 0.25f, 1e-6f);
  EXPECT_NEAR(c.g, 0.5f, 1e-6f);
  EXPECT_NEAR(c.b, 1.0f, 1e-6f);
  EXPECT_EQ(c.a, 1.0f);
}

TEST_P(ReferenceRenderer, PointLightsFallOffWithTheSquareOfTheDistance) {
  scene::Scene s = groundScene(GetParam());
  s.lights.push_back({LightType::Point, glm::dvec3(4.0), {0, 2, 0}});
  EXPECT_NEAR(centre(render(s, Backend::Cpu).image).g, 1.0f, 1e-6f);  // 4 / 2²
}

TEST_P(ReferenceRenderer, SpotLightsFadeBetweenTheirCones) {
  scene::Scene s = groundScene(GetParam());
  Light spot{LightType::Spot, glm::dvec3(4.0), {0, 2, 0}, {0, -1, 0}, 10.0, 20.0};
  s.lights.push_back(spot);
  EXPECT_NEAR(centre(render(s, Backend::Cpu).image).g, 1.0f, 1e-6f);  // on the axis: full strength
  s.lights[0].direction = glm::normalize(glm::dvec3(std::tan(glm::radians(25.0)), -1, 0));
  EXPECT_EQ(centre(render(s, Backend::Cpu).image).g, 0.0f);  // 25° off the axis: outside the outer cone
}

TEST_P(ReferenceRenderer, AnOccluderCastsAShadow) {
  scene::Scene s = groundScene(GetParam());
  s.lights.push_back({LightType::Directional, glm::dvec3(1.0), {}, {0, -1, 0}});
  scene::Object roof;
  roof.name = "roof";
  roof.cage = plane(10.0, 8.0);  // above the camera, which looks down and never sees it
  s.objects.push_back(std::move(roof));
  const glm::vec4 c = centre(render(s, Backend::Cpu).image);
  EXPECT_EQ(glm::vec3(c), glm::vec3(0.0f));
  EXPECT_EQ(c.a, 1.0f);
}

TEST_P(ReferenceRenderer, AovsAgreeWithEachOtherAndWithTheCamera) {
  scene::Scene s = scene::sceneFromCage(scene::loadObjCage(std::string(FACET_CAGE_DIR) + "/creased_box.obj"));
  s.render.width = s.render.height = 24;
  s.render.method = GetParam();
  RenderReport report = render(s, Backend::Cpu);
  const Image& image = report.image;
  const rules::f64::CameraFrame frame = camera::cameraFrame(s.camera, image.width, image.height);
  int covered = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = image.index(x, y);
      if (image.beauty[i].a == 0) {
        EXPECT_TRUE(std::isinf(image.depth[i]));
        EXPECT_EQ(image.patchId[i], Image::kNoId);
        continue;
      }
      ++covered;
      const glm::dvec3 direction = rules::f64::camera_ray_direction(frame, x + 0.5, y + 0.5, image.width, image.height);
      const glm::dvec3 expected = frame.eye + double(image.depth[i]) * direction;
      EXPECT_LT(glm::distance(glm::dvec3(image.position[i]), expected), 1e-5 * image.depth[i]) << x << "," << y;
      EXPECT_NEAR(glm::length(image.shadingNormal[i]), 1.0f, 1e-5f);
      EXPECT_LT(glm::dot(glm::dvec3(image.geometricNormal[i]), direction), 0.0) << "geometric normals face the eye";
      EXPECT_LT(image.patchId[i], std::uint32_t(report.patches));
      EXPECT_LT(image.faceId[i], std::uint32_t(s.objects[0].cage.faceCount()));
    }
  }
  // The framing puts the object in the middle and leaves a margin around it.
  EXPECT_GT(covered, image.width * image.height / 8);
  EXPECT_LT(covered, image.width * image.height);
}

// Far from the origin double resolves less than the default tolerance of
// 1e-9 diagonals: the exact method's tolerance and the shadow rays' offset
// follow the coordinates' precision (cpu::precisionFloor), so the convex
// blob 1e12 away renders under a white sky as it does near the origin: no
// ray slips through it and none of its shadow rays finds it again.
TEST(ReferenceRendererFar, ABlobFarFromTheOriginRendersAsNearIt) {
  scene::Scene near = testing::blobUnder(
      testing::lambertian(0.8),
      std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0))), 24);
  near.render.method = scene::IntersectionMethod::Exact;
  near.environment->method = scene::IblMethod::Sampled;
  near.environment->samples = 4;
  scene::Scene far = near;
  const glm::dvec3 away(1e12, -3e11, 0.0);
  for (glm::dvec3& p : far.objects.front().cage.positions) p += away;
  far.camera.eye += away;
  far.camera.target += away;
  Renderer renderer;
  const Image a = renderer.render(near, Backend::Cpu).image, b = renderer.render(far, Backend::Cpu).image;
  int covered = 0, differ = 0;
  double nearSum = 0, farSum = 0;
  for (std::size_t p = 0; p < a.pixelCount(); ++p) {
    differ += a.beauty[p].a != b.beauty[p].a;
    if (a.beauty[p].a < 1.0f || b.beauty[p].a < 1.0f) continue;
    ++covered;
    nearSum += a.beauty[p].g;
    farSum += b.beauty[p].g;
  }
  ASSERT_GT(covered, 100);
  EXPECT_LE(differ, int(a.pixelCount() / 50)) << "coverage changed";
  EXPECT_NEAR(farSum / covered, nearSum / covered, 0.01 * nearSum / covered);
}

// The tessellated method's grids are held to the process's memory limit
// before any is diced: at 256 x 256 a patch's grid takes 1.6 MB.
TEST(ReferenceRendererMemory, GridsPastTheMemoryLimitAreRefusedBeforeTheyAreDiced) {
  scene::Scene s = scene::sceneFromCage(scene::loadObjCage(std::string(FACET_CAGE_DIR) + "/creased_box.obj"));
  s.render.width = s.render.height = 8;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.render.tessellationRate = 256;
  const scene::SceneGeometry geometry = scene::buildGeometry(s);
  const testing::ScopedEnv limit("FACET_MEMORY_LIMIT", "64");
  EXPECT_THAT([&] { cpu::renderReference(s, geometry); },
              ::testing::ThrowsMessage<std::invalid_argument>(::testing::AllOf(
                  ::testing::HasSubstr("render.tess_level (--tess-level) 256: the CPU reference's grids of "),
                  ::testing::HasSubstr("the limit is 0.1 GB (FACET_MEMORY_LIMIT); lower the dicing rate"))));
  // The same surface at a rate that fits renders.
  s.render.tessellationRate = 8;
  EXPECT_NO_THROW(cpu::renderReference(s, scene::buildGeometry(s)));
}

INSTANTIATE_TEST_SUITE_P(Methods, ReferenceRenderer,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         [](const auto& info) {
                           return info.param == scene::IntersectionMethod::Exact ? "Exact" : "Tessellated";
                         });

}  // namespace
}  // namespace facet

// glTF's one-sided surfaces (doubleSided false) on both backends
// (docs/rendering.md, "One-sided surfaces"): a quad is seen from its front
// only, its front being the side its winding faces in world space, mirrored
// node or not; and every ray passes over a back face, so that a one-sided
// quad shadows the points its front faces and no others. Each render is
// checked on both backends, and the two against each other.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <random>
#include <string>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/cages.h"
#include "tests/support/gpu_device.h"
#include "tests/support/path_parity.h"
#include "tests/support/textured_gltf.h"

namespace facet {
namespace {

class OneSided : public gpu::testing::GpuTest, public ::testing::WithParamInterface<scene::IntersectionMethod> {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    dir_ = std::filesystem::temp_directory_path() / ("facet_one_sided_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  // Both backends' renders of `scene`, which must agree: within parity's
  // tolerances where they cover pixels, and on which pixels they cover.
  std::pair<Image, Image> renderBoth(const scene::Scene& scene) {
    const scene::SceneGeometry geometry = scene::buildGeometry(scene);
    Image reference = cpu::renderReference(scene, geometry);
    if (!renderer_) renderer_ = std::make_unique<gpu_backend::GpuRenderer>(device_);
    Image gpu = renderer_->render(scene, geometry).image;
    for (std::size_t i = 0; i < gpu.pixelCount(); ++i) EXPECT_EQ(reference.beauty[i].a, gpu.beauty[i].a) << i;
    if (std::any_of(gpu.beauty.begin(), gpu.beauty.end(), [](const glm::vec4& b) { return b.a > 0.0f; })) {
      const analysis::ParityReport parity = analysis::compareImages(reference, gpu);
      EXPECT_TRUE(parity.pass) << analysis::describe(parity);
    }
    return {std::move(reference), std::move(gpu)};
  }

  void TearDown() override {
    renderer_.reset();
    std::filesystem::remove_all(dir_);
    GpuTest::TearDown();
  }

  std::filesystem::path dir_;
  std::unique_ptr<gpu_backend::GpuRenderer> renderer_;  // one per test: its pipelines compiled once
};

// The quad of textured_gltf.h (facing +z as wound), optionally mirrored by
// its node's scale (the loader then reverses its winding, as glTF says),
// seen from +z or -z.
scene::Scene quad(const std::filesystem::path& dir, bool doubleSided, bool mirrored, bool fromFront,
                  scene::IntersectionMethod method) {
  nlohmann::json node = {{"mesh", 0}};
  if (mirrored) node["scale"] = {-1.0, 1.0, 1.0};
  const std::string name = std::string("quad") + (doubleSided ? "2" : "1") + (mirrored ? "m" : "");
  scene::Scene scene = scene::loadScene(facet::testing::writeTexturedQuad(
      dir, name,
      {{"nodes", {node}},
       {"materials", {{{"doubleSided", doubleSided}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}}}}}));
  scene.camera = {{0.0, 0.0, fromFront ? 3.0 : -3.0}, glm::dvec3(0.0), {0.0, 1.0, 0.0}, 30.0};
  scene.lights = {{scene::LightType::Point, glm::dvec3(4.0), {0.3, 0.4, fromFront ? 2.0 : -2.0}}};
  scene.render.width = scene.render.height = 12;
  scene.render.method = method;
  return scene;
}

TEST_P(OneSided, AQuadIsSeenFromItsFrontOnly) {
  for (bool mirrored : {false, true})
    for (bool doubleSided : {false, true})
      for (bool fromFront : {true, false}) {
        SCOPED_TRACE(::testing::Message() << "mirrored " << mirrored << ", double-sided " << doubleSided
                                          << ", from the front " << fromFront);
        const scene::Scene scene = quad(dir_, doubleSided, mirrored, fromFront, GetParam());
        EXPECT_TRUE(scene.warnings.empty());
        const bool seen = fromFront || doubleSided;
        const auto [reference, gpu] = renderBoth(scene);
        for (const Image* image : {&reference, &gpu}) {
          const glm::vec4 centre = image->beauty[image->index(6, 6)];
          EXPECT_EQ(centre.a, seen ? 1.0f : 0.0f);
          if (seen) {
            EXPECT_GT(centre.r, 0.05f);  // lit: the light is on the side it is seen from
          }
        }
      }
}

// A grey floor facing +z and, one unit above it, a black square facing down
// (towards the floor) or up (towards the camera and the light, which shines
// down and towards +x, so that the square's shadow falls at x in [0.5, 1.5]).
scene::Scene floorAndSquare(bool oneSided, bool facingDown, scene::IntersectionMethod method) {
  scene::Scene scene;
  scene.materials.resize(2);
  scene.materials[0].diffuse = glm::dvec3(0.8);
  scene.materials[1].diffuse = glm::dvec3(0.0);
  scene::Object floor;
  floor.name = "floor";
  floor.cage = scene::testing::singleFace({{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}});
  floor.subdivision = scene::Subdivision::None;
  scene::Object square = floor;
  square.name = "square";
  square.cage = facingDown ? scene::testing::singleFace({{-.5, -.5, 1}, {-.5, .5, 1}, {.5, .5, 1}, {.5, -.5, 1}})
                           : scene::testing::singleFace({{-.5, -.5, 1}, {.5, -.5, 1}, {.5, .5, 1}, {-.5, .5, 1}});
  square.material = 1;
  square.oneSided = oneSided;
  scene.objects = {floor, square};
  scene.camera = {{0.0, 0.0, 5.0}, glm::dvec3(0.0), {0.0, 1.0, 0.0}, 50.0};
  scene.lights = {
      {scene::LightType::Directional, glm::dvec3(1.0), glm::dvec3(0.0), glm::normalize(glm::dvec3(1.0, 0.0, -1.0))}};
  scene.render.width = scene.render.height = 24;
  scene.render.method = method;
  return scene;
}

// The mean red of the pixels whose centre ray hit the floor (z = 0) within
// x in [x0, x1], |y| < 0.4.
double floorRed(const Image& image, double x0, double x1) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    const glm::vec3 p = image.position[i];
    if (image.beauty[i].a == 1.0f && std::abs(p.z) < 1e-3f && p.x > x0 && p.x < x1 && std::abs(p.y) < 0.4f)
      sum += image.beauty[i].r, ++count;
  }
  EXPECT_GT(count, 0);
  return count > 0 ? sum / count : 0.0;
}

TEST_P(OneSided, EveryRayPassesOverABackFace) {
  for (bool oneSided : {false, true})
    for (bool facingDown : {false, true}) {
      SCOPED_TRACE(::testing::Message() << "one-sided " << oneSided << ", facing down " << facingDown);
      const auto [reference, gpu] = renderBoth(floorAndSquare(oneSided, facingDown, GetParam()));
      // The camera above sees the square unless it faces away; the floor
      // under the light's path through it is in shadow unless the square
      // faces away from the floor.
      const bool seen = !oneSided || !facingDown, shadows = !oneSided || facingDown;
      for (const Image* image : {&reference, &gpu}) {
        const std::size_t centre = image->index(12, 12);
        EXPECT_NEAR(image->position[centre].z, seen ? 1.0f : 0.0f, 1e-3f);
        const double lit = floorRed(*image, -2.0, -1.0), shadow = floorRed(*image, 0.7, 1.3);
        EXPECT_GT(lit, 0.1);
        if (shadows)
          EXPECT_LT(shadow, 1e-6);
        else
          EXPECT_GT(shadow, 0.5 * lit);
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, OneSided,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         facet::testing::methodName);

}  // namespace
}  // namespace facet

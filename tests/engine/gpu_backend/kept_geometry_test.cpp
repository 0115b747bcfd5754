// A GPU renderer keeps its last packed and diced geometry for the next render
// of the same geometry (its serial), eye and materials
// (engine/gpu_backend/gpu_renderer.h): each render still shows its own
// scene, the same image as a fresh renderer's, whatever changed in between.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/gpu_device.h"

namespace facet {
namespace {

materials::Material presetMaterial(const char* name) {
  materials::MaterialSpec spec;
  spec.preset = name;
  spec.roughness = 0.3;
  return testing::buildTestMaterial(spec);
}

using KeptGeometry = gpu::testing::GpuTest;

TEST(GeometrySerial, EachBuildHasItsOwnAndAMoveKeepsIt) {
  const scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  scene::SceneGeometry first = scene::buildGeometry(scene);
  const scene::SceneGeometry second = scene::buildGeometry(scene);
  EXPECT_NE(first.serial, 0u);
  EXPECT_NE(first.serial, second.serial);
  const std::uint64_t serial = first.serial;
  const scene::SceneGeometry moved = std::move(first);
  EXPECT_EQ(moved.serial, serial);
}

TEST_F(KeptGeometry, EachRenderShowsItsOwnScene) {
  scene::Scene first = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  first.render.width = 16;
  first.render.height = 12;
  first.materials.push_back(presetMaterial("copper"));
  const scene::SceneGeometry geometry = scene::buildGeometry(first);

  scene::Scene otherMaterial = first;
  otherMaterial.objects[0].material = 1;
  scene::Scene otherEye = first;
  otherEye.camera.eye += glm::dvec3(0.3, -0.2, 0.1);
  scene::Scene oneSidedGlass = first;
  oneSidedGlass.objects[0].oneSided = true;
  scene::Scene culled = oneSidedGlass;
  oneSidedGlass.materials[0] = testing::buildTestMaterial(testing::glassSpec(1.5));
  culled.materials[0] = presetMaterial("gold");

  gpu_backend::GpuRenderer kept(device_);
  const Image firstImage = kept.render(first, geometry).image;
  for (const scene::Scene* other : {&otherMaterial, &otherEye, &culled, &oneSidedGlass}) {
    const Image keptImage = kept.render(*other, geometry).image;
    gpu_backend::GpuRenderer fresh(device_);
    EXPECT_EQ(keptImage.beauty, fresh.render(*other, geometry).image.beauty);
    EXPECT_EQ(keptImage.patchId, fresh.render(*other, geometry).image.patchId);
  }
  EXPECT_EQ(kept.render(first, geometry).image.beauty, firstImage.beauty);
  EXPECT_EQ(kept.render(first, scene::buildGeometry(first)).image.beauty, firstImage.beauty) << "another build";
}

TEST_F(KeptGeometry, TheSameGeometryIsNeitherPackedNorDicedAgain) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  scene.render.width = 16;
  scene.render.height = 12;
  scene.render.method = scene::IntersectionMethod::Tessellated;
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  gpu_backend::GpuRenderer renderer(device_);
  const auto diced = [&](const scene::SceneGeometry& g) {
    for (const StageTime& stage : renderer.render(scene, g).stageMilliseconds)
      if (stage.stage == Stage::DiceGrid) return true;
    return false;
  };
  EXPECT_TRUE(diced(geometry));
  EXPECT_FALSE(diced(geometry));
  EXPECT_FALSE(diced(scene::buildGeometry(scene))) << "another build of the same geometry hashes the same";
  scene.camera.eye += glm::dvec3(0.0, 0.5, 0.0);
  EXPECT_TRUE(diced(geometry)) << "rebased on another eye";
}

}  // namespace
}  // namespace facet

// A crop or a tile of the CPU reference is the same pixels as the whole
// render, bit for bit: sampling, random numbers and AOVs follow the pixel.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "engine/renderer.h"
#include "scenes/obj_cage.h"
#include "tests/support/environment_maps.h"
#include "tests/support/image_windows.h"

namespace facet {
namespace {

// The cube's limit surface under a sun-and-sky environment, sampled IBL
// with shadow rays and a punctual light: every random number a pixel draws.
scene::Scene sampledScene() {
  scene::Scene s;
  s.materials.emplace_back();
  scene::Object cube;
  cube.cage = scene::loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  s.objects.push_back(std::move(cube));
  s.camera.eye = {1.5, 1.0, 3.5};
  s.camera.verticalFovDegrees = 35;
  s.render.width = 37;
  s.render.height = 29;
  s.render.samplesPerPixel = 4;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.lights.push_back({});
  s.environment.emplace();
  s.environment->map =
      std::make_shared<const scene::EnvironmentMap>(ibl::testing::mapOf(32, 16, ibl::testing::skyWithSun));
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->samples = 2;
  return s;
}

TEST(ReferenceRendererCrop, CropsAndTilesAreThePixelsOfTheWholeRender) {
  const scene::Scene scene = sampledScene();
  Renderer renderer;
  const RenderReport whole = renderer.render(scene, Backend::Cpu);
  ASSERT_EQ(whole.image.width, 37);
  for (const PixelRect& crop : {PixelRect{3, 2, 30, 17}, PixelRect{0, 28, 37, 29}, PixelRect{36, 0, 37, 29},
                                tileRows(37, 29, 1, 3), tileRows(37, 29, 2, 3)}) {
    const RenderReport part = renderer.render(scene, Backend::Cpu, {}, {crop, 3});
    EXPECT_EQ(part.window, crop);
    EXPECT_THAT(testing::pixelsThatDiffer(whole.image, part.image, crop), ::testing::IsEmpty()) << crop.text();
  }
}

TEST(ReferenceRendererCrop, ThreadCountChangesNoPixel) {
  const scene::Scene scene = sampledScene();
  Renderer renderer;
  const RenderReport many = renderer.render(scene, Backend::Cpu, {}, {std::nullopt, 4});
  const RenderReport one = renderer.render(scene, Backend::Cpu, {}, {std::nullopt, 1});
  EXPECT_THAT(one.device, ::testing::HasSubstr("1 threads"));
  EXPECT_THAT(testing::pixelsThatDiffer(many.image, one.image, many.window), ::testing::IsEmpty());
}

TEST(ReferenceRendererCrop, CropOutsideTheImageIsRefused) {
  const scene::Scene scene = sampledScene();
  Renderer renderer;
  EXPECT_THROW(renderer.render(scene, Backend::Cpu, {}, {PixelRect{0, 0, 38, 29}}), std::invalid_argument);
  EXPECT_THROW(renderer.render(scene, Backend::Cpu, {}, {PixelRect{5, 5, 5, 9}}), std::invalid_argument);
}

}  // namespace
}  // namespace facet

// A crop or a tile on the GPU backend: the same pixels as its whole render
// (the kernels see the full image's pixel indices), and within the parity
// tolerances of the CPU reference's crop.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/parity.h"
#include "engine/renderer.h"
#include "scenes/scene_file.h"
#include "tests/support/image_windows.h"

namespace facet {
namespace {

TEST(GpuCrop, CropsAndTilesAreThePixelsOfTheWholeRender) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "superball.obj");
  scene.render.width = 45;
  scene.render.height = 31;
  scene.render.samplesPerPixel = 4;
  Renderer renderer;
  const RenderReport whole = renderer.render(scene, Backend::Gpu);
  for (const PixelRect& crop : {PixelRect{4, 3, 40, 20}, tileRows(45, 31, 0, 4), tileRows(45, 31, 3, 4)}) {
    const RenderReport part = renderer.render(scene, Backend::Gpu, {}, {crop});
    EXPECT_THAT(testing::pixelsThatDiffer(whole.image, part.image, crop), ::testing::IsEmpty()) << crop.text();
    const RenderReport reference = renderer.render(scene, Backend::Cpu, {}, {crop});
    // A tile holds a few rows of the image: every covered pixel is judged,
    // and the top one, all background, has none to judge.
    analysis::ParityTolerances everyPixel;
    everyPixel.minCoverage = 1;
    const analysis::ParityReport parity = analysis::compareImages(reference.image, part.image, everyPixel);
    const bool background = parity.covered == 0 && parity.coveragePass;
    EXPECT_TRUE(parity.pass || background) << crop.text() << "\n" << analysis::describe(parity);
  }
}

}  // namespace
}  // namespace facet

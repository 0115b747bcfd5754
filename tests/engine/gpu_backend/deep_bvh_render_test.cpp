// OpenSubdiv's catmark_bishop, whose SAH tree collapses to top levels as
// deep as the traversal's whole stack (engine/gpu_backend/top_levels.h),
// rendered on the device: every pixel hits what the CPU reference hits, at
// its depth.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"

namespace facet {
namespace {

class DeepBvhRender : public gpu::testing::GpuTest, public ::testing::WithParamInterface<scene::IntersectionMethod> {};

TEST_P(DeepBvhRender, TheBishopHitsWhatTheReferenceHits) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "catmark_bishop.obj");
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.method = GetParam();
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  ASSERT_GT(geometry.patchCount(), 90000);
  gpu_backend::GpuRenderer renderer(device_);
  const Image gpu = renderer.render(scene, geometry).image;
  const Image cpu = cpu::renderReference(scene, geometry);
  int covered = 0, coverage = 0, depth = 0;
  for (std::size_t p = 0; p < gpu.patchId.size(); ++p) {
    const bool hit = gpu.patchId[p] != Image::kNoId;
    if (hit != (cpu.patchId[p] != Image::kNoId)) ++coverage;
    if (!hit || cpu.patchId[p] == Image::kNoId) continue;
    ++covered;
    if (std::abs(gpu.depth[p] - cpu.depth[p]) > 1e-4 * cpu.depth[p]) ++depth;
  }
  EXPECT_GT(covered, 200);
  // A silhouette pixel may go either way between float and double.
  EXPECT_LE(coverage, 2);
  EXPECT_LE(depth, 2);
}

INSTANTIATE_TEST_SUITE_P(Methods, DeepBvhRender,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         [](const auto& info) {
                           return info.param == scene::IntersectionMethod::Exact ? "exact" : "tess";
                         });

}  // namespace
}  // namespace facet

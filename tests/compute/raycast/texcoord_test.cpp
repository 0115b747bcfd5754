// surface_texcoord (compute/raycast/common/texcoord.glsl) in float on the device,
// reading the packed texcoord texels, against
// SubdivisionSurface::evaluateTexcoord (OpenSubdiv, double): the values and
// the derivatives that tangents and texture footprints are built from.
#include <glm/geometric.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include "engine/gpu_backend/gpu_scene.h"
#include "facet_raycast_test_kernels/spirv.h"
#include "scenes/scene_file.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

struct TexcoordCase {
  std::uint32_t firstTexcoord;
  float s, t;
  std::uint32_t pad;
};

class TexcoordKernel : public gpu::testing::GpuTest {};

TEST_F(TexcoordKernel, MatchesOpenSubdivsFaceVaryingPatches) {
  const scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "uv_checker_cube.obj");
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const scene::SubdivisionSurface& surface = geometry.objects[0].surface;
  const GpuScene packed = packScene(scene, geometry, scene.camera.eye, 0.0, false);
  std::vector<TexcoordCase> cases;
  for (const layout::PatchRecord& record : packed.patches)
    for (float s : {0.0f, 0.3f, 1.0f})
      for (float t : {0.0f, 0.55f, 1.0f}) cases.push_back({record.firstTexcoord, s, t, 0});
  // A patch without texture coordinates reads as zero.
  cases.push_back({layout::FACET_NO_TEXCOORDS, 0.5f, 0.5f, 0});

  gpu::Buffer texcoords = upload(packed.texcoords, gpu::BufferUsage::Texel);
  gpu::Buffer points = upload(packed.points, gpu::BufferUsage::Texel);
  gpu::Buffer caseBuffer = upload(cases);
  gpu::Buffer results = poisoned(cases.size() * 3 * sizeof(glm::vec2));
  auto pipeline = derivedPipeline("texcoord", test_spirv::texcoord_eval);
  auto groupLayout = pipeline.getBindGroupLayout(0);
  // The bindings the kernel kept (glslang may drop the unread patchPoints).
  const std::map<std::uint32_t, const gpu::Buffer*> buffers = {
      {0, &caseBuffer}, {1, &results}, {3, &points}, {28, &texcoords}};
  std::vector<gpu::BindGroupEntry> entries;
  for (const gpu::BindGroupLayoutEntry& entry : groupLayout.entries())
    entries.push_back({entry.binding, buffers.at(entry.binding)});
  auto group = device_.createBindGroup({"texcoord", &groupLayout, std::move(entries)});
  dispatchOnce(pipeline, group, std::uint32_t(cases.size() + 63) / 64);
  const std::vector<glm::vec2> out = readBack<glm::vec2>(results);

  double worstValue = 0, worstDerivative = 0;
  std::size_t i = 0;
  for (const layout::PatchRecord& record : packed.patches)
    for (float s : {0.0f, 0.3f, 1.0f})
      for (float t : {0.0f, 0.55f, 1.0f}) {
        const scene::LimitTexcoord osd = surface.evaluateTexcoord(
            int(record.sourcePatch), record.faceU0 + s * double(record.faceSize), record.faceV0 + t * double(record.faceSize));
        worstValue = std::max(worstValue, glm::distance(glm::dvec2(out[3 * i]), osd.uv));
        // (s, t) derivatives are the face ones times the patch's size.
        worstDerivative = std::max({worstDerivative,
                                    glm::distance(glm::dvec2(out[3 * i + 1]), osd.du * double(record.faceSize)),
                                    glm::distance(glm::dvec2(out[3 * i + 2]), osd.dv * double(record.faceSize))});
        ++i;
      }
  EXPECT_LT(worstValue, 1e-6);
  EXPECT_LT(worstDerivative, 1e-5);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(out[3 * i + std::size_t(k)], glm::vec2(0.0f));
}

}  // namespace
}  // namespace facet::gpu_backend

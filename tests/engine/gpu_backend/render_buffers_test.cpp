// The up-front check of a packed scene against a device's limits
// (engine/gpu_backend/render_buffers.h, checkGeometryLimits), with limits
// lowered to just below what the scene needs: the error names the array,
// its need, the limit and what to do, and a limit that holds passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "engine/gpu_backend/render_buffers.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

gpu::Limits roomy() {
  gpu::Limits limits;
  limits.maxTexelBufferElements = std::uint64_t(1) << 27;
  limits.maxBufferSize = std::uint64_t(1) << 31;
  limits.maxStorageBufferBindingSize = std::uint64_t(1) << 27;
  return limits;
}

std::string errorOf(const GpuScene& packed, const gpu::Limits& limits) {
  try {
    checkGeometryLimits(packed, limits, "test adapter");
  } catch (const gpu::Error& e) {
    return e.what();
  }
  return "";
}

class GeometryLimits : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    const scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "suzanne.obj");
    packed_ = packScene(scene, scene::buildGeometry(scene), scene.camera.eye, 0.0, GetParam());
  }
  // The texels of the largest texel array.
  std::uint64_t largestTexelArray() const {
    return std::max({packed_.nodeCount * layout::FACET_BVH4_TEXELS, packed_.gridVertices, packed_.edgeMidpoints,
                     packed_.cellBounds, packed_.patches.size() * layout::FACET_PATCH_RECORD_TEXELS,
                     std::uint64_t(packed_.headers.size()), std::uint64_t(packed_.points.size())});
  }
  GpuScene packed_;
};

TEST_P(GeometryLimits, PassWhereTheyHold) {
  EXPECT_EQ(errorOf(packed_, roomy()), "");
  gpu::Limits exact = roomy();
  exact.maxTexelBufferElements = largestTexelArray();
  exact.maxBufferSize = 16 * largestTexelArray();
  exact.maxStorageBufferBindingSize = packed_.objects.size() * sizeof(layout::ObjectRange);
  exact.maxStorageBufferBindingSize =
      std::max<std::uint64_t>(exact.maxStorageBufferBindingSize, packed_.refitOrder.size() * sizeof(std::uint32_t));
  EXPECT_EQ(errorOf(packed_, exact), "");
}

TEST_P(GeometryLimits, NameTheArrayItsNeedAndTheLimit) {
  const std::uint64_t texels = largestTexelArray();
  gpu::Limits fewTexels = roomy();
  fewTexels.maxTexelBufferElements = texels - 1;
  const std::string texelError = errorOf(packed_, fewTexels);
  EXPECT_NE(texelError.find(" need " + std::to_string(texels) + " texels"), std::string::npos) << texelError;
  EXPECT_NE(texelError.find("test adapter addresses at most " + std::to_string(texels - 1)), std::string::npos)
      << texelError;

  gpu::Limits smallBuffers = roomy();
  smallBuffers.maxBufferSize = 16 * texels - 1;
  const std::string bufferError = errorOf(packed_, smallBuffers);
  EXPECT_NE(bufferError.find("maxBufferSize is " + std::to_string(16 * texels - 1)), std::string::npos) << bufferError;

  gpu::Limits smallBindings = roomy();
  smallBindings.maxStorageBufferBindingSize = packed_.refitOrder.size() * sizeof(std::uint32_t) - 1;
  const std::string bindingError = errorOf(packed_, smallBindings);
  EXPECT_NE(bindingError.find("the refit order need " + std::to_string(packed_.refitOrder.size() * 4) + " bytes"),
            std::string::npos)
      << bindingError;
  EXPECT_NE(bindingError.find("--backend cpu"), std::string::npos) << bindingError;
}

// The patch records are read through a texel buffer: a scene whose records
// exceed the storage binding limit still passes.
TEST_P(GeometryLimits, PatchRecordsAreNotBoundByTheStorageBindingLimit) {
  gpu::Limits tinyBindings = roomy();
  tinyBindings.maxStorageBufferBindingSize =
      std::max(packed_.objects.size() * sizeof(layout::ObjectRange), packed_.refitOrder.size() * sizeof(std::uint32_t));
  ASSERT_GT(packed_.patches.size() * sizeof(layout::PatchRecord), tinyBindings.maxStorageBufferBindingSize);
  EXPECT_EQ(errorOf(packed_, tinyBindings), "");
}

INSTANTIATE_TEST_SUITE_P(Methods, GeometryLimits, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "tess" : "exact"; });

}  // namespace
}  // namespace facet::gpu_backend

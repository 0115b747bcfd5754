// The up-front check of a packed scene against a device's limits
// (engine/gpu_backend/render_buffers.h, checkGeometryLimits), with limits
// lowered to just below what the scene needs: the error names the array,
// its need, the limit and what to do, and a limit that holds passes. And the
// band's size (bandPixelCount) against lowered binding limits: bands get
// smaller, and only a pixel too large for one binding is an error.
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

constexpr std::uint64_t kBudget = std::uint64_t(48) << 20;

std::string bandError(const BandShape& shape, const gpu::Limits& limits) {
  try {
    bandPixelCount(shape, 1 << 16, kBudget, limits, "test adapter", "the advice");
  } catch (const gpu::Error& e) {
    return e.what();
  }
  return "";
}

TEST(BandPixels, ShrinkSoThatEveryBindingFitsTheDevice) {
  // The sampled environment's many slots: 17 camera rays of 64 slots each.
  const BandShape shape{17, 64, true};
  const std::uint64_t shadowBytes = 17 * 64 * sizeof(layout::ShadowRayRecord);  // the largest per pixel
  const std::uint64_t roomyBand = bandPixelCount(shape, 1 << 16, kBudget, roomy(), "a", "");
  for (const std::uint64_t binding : {std::uint64_t(1) << 20, shadowBytes * 3 + 1, shadowBytes}) {
    gpu::Limits limits = roomy();
    limits.maxStorageBufferBindingSize = binding;
    const std::uint64_t band = bandPixelCount(shape, 1 << 16, kBudget, limits, "a", "");
    EXPECT_EQ(band, binding / shadowBytes) << binding;  // the most whose shadow rays fit one binding
    EXPECT_LT(band, roomyBand);
    gpu::Limits smallBuffers = roomy();
    smallBuffers.maxBufferSize = binding;  // the same bound from the buffer size
    EXPECT_EQ(bandPixelCount(shape, 1 << 16, kBudget, smallBuffers, "a", ""), band);
  }
  // The budget bounds the band where the device does not, and the image bounds it too.
  EXPECT_LE(roomyBand * (shadowBytes + 17 * 64 * 16), kBudget);
  EXPECT_GT(roomyBand, 100u);
  EXPECT_EQ(bandPixelCount(shape, 7, kBudget, roomy(), "a", ""), 7u);
}

TEST(BandPixels, APixelThatFitsNoBindingNamesItsRaysTheLimitAndTheSettings) {
  // --spp 1024 (1025 camera rays) with a sampled environment of 4096 samples
  // and one light: 8193 slots per ray, 302 MB of shadow rays in one pixel.
  const BandShape shape{1025, 8193, false};
  const std::string error = bandError(shape, roomy());
  EXPECT_NE(error.find("one pixel's shadow rays need " + std::to_string(1025ull * 8193 * 36) + " bytes"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("1025 camera rays, 8193 shadow-ray slots each"), std::string::npos) << error;
  EXPECT_NE(error.find("test adapter binds at most " + std::to_string(std::uint64_t(1) << 27) + ": the advice"),
            std::string::npos)
      << error;
  // One pixel exactly at the limit still renders, alone.
  gpu::Limits exact = roomy();
  exact.maxStorageBufferBindingSize = 1025ull * 8193 * 36;
  EXPECT_EQ(bandError(shape, exact), "");
}

TEST(BandPixels, TheAdviceNamesTheSettingsThatMakeTheSlots) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "suzanne.obj");
  scene.render.samplesPerPixel = 1024;
  scene.environment = scene::Environment{};
  scene.environment->samples = 4096;
  const std::string advice = bandAdvice(scene);
  EXPECT_NE(advice.find("--spp, 1024"), std::string::npos) << advice;
  EXPECT_NE(advice.find("--ibl-samples, 4096"), std::string::npos) << advice;
  EXPECT_NE(advice.find("--backend cpu"), std::string::npos) << advice;
}

}  // namespace
}  // namespace facet::gpu_backend

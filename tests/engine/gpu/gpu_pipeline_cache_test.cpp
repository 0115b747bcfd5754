// The device's pipeline cache and pipelines made together: the cache's data
// names its adapter, a device started from it makes pipelines that compute
// what a fresh one's do, and a batch of pipelines is each descriptor's own.
#include <cstring>

#include "facet_test_kernels/spirv.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

// The fill kernel of specialized_fill.comp: i * kScale, or its negation.
std::vector<float> expectedFill(std::uint32_t n, float scale, bool negate) {
  std::vector<float> values(n);
  for (std::uint32_t i = 0; i < n; ++i) values[i] = negate ? -(float(i) * scale) : float(i) * scale;
  return values;
}

class PipelineCacheTest : public GpuTest {
 protected:
  std::vector<float> fill(Device& device, const ComputePipeline& pipeline, std::uint32_t n) {
    std::swap(device, device_);  // the fixture's helpers work on device_
    Buffer out = poisoned(n * sizeof(float));
    auto layout = pipeline.getBindGroupLayout(0);
    auto group = device_.createBindGroup({"fill", &layout, {{0, &out}}});
    dispatchOnce(pipeline, group, (n + 63) / 64);
    std::vector<float> values = readBack<float>(out);
    std::swap(device, device_);
    return values;
  }
};

TEST_F(PipelineCacheTest, DataStartsWithAVulkanHeaderNamingTheAdapter) {
  ShaderModule shader = module("fill", test_spirv::specialized_fill);
  device_.createComputePipeline({"fill", nullptr, &shader, "main", {{"0", 64.0}}});
  const std::vector<std::byte> data = device_.pipelineCacheData();
  const AdapterInfo& adapter = device_.adapterInfo();
  ASSERT_GE(data.size(), 32u);
  std::uint32_t header[4];
  std::memcpy(header, data.data(), sizeof header);
  EXPECT_GE(header[0], 32u);  // the header's length
  EXPECT_EQ(header[1], 1u);   // VK_PIPELINE_CACHE_HEADER_VERSION_ONE
  EXPECT_EQ(header[2], adapter.vendorId);
  EXPECT_EQ(header[3], adapter.deviceId);
  EXPECT_EQ(std::memcmp(data.data() + 16, adapter.pipelineCacheUuid.data(), 16), 0);
}

TEST_F(PipelineCacheTest, ADeviceStartedFromTheDataComputesTheSame) {
  ShaderModule shader = module("fill", test_spirv::specialized_fill);
  ComputePipeline first =
      device_.createComputePipeline({"fill", nullptr, &shader, "main", {{"kScale", 2.5}, {"0", 64.0}}});
  const std::vector<float> fresh = fill(device_, first, 500);
  EXPECT_EQ(fresh, expectedFill(500, 2.5f, false));

  Device second = instance_.requestAdapter().requestDevice({"cached", device_.pipelineCacheData()});
  ShaderModule again = second.createShaderModule({"fill", test_spirv::specialized_fill});
  ComputePipeline cached =
      second.createComputePipeline({"fill", nullptr, &again, "main", {{"kScale", 2.5}, {"0", 64.0}}});
  EXPECT_EQ(fill(second, cached, 500), fresh);
  // Its cache holds at least what it was given.
  EXPECT_GE(second.pipelineCacheData().size(), device_.pipelineCacheData().size());
  second.queue().waitIdle();
}

TEST_F(PipelineCacheTest, ABatchMakesEachDescriptorsPipeline) {
  ShaderModule shader = module("fill", test_spirv::specialized_fill);
  std::vector<ComputePipelineDescriptor> descriptors;
  for (int i = 0; i < 6; ++i)
    descriptors.push_back({"fill " + std::to_string(i),
                           nullptr,
                           &shader,
                           "main",
                           {{"kScale", 1.0 + i}, {"kNegate", double(i % 2)}, {"0", 64.0}}});
  std::vector<ComputePipeline> pipelines = device_.createComputePipelines(descriptors, 3);
  ASSERT_EQ(pipelines.size(), descriptors.size());
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(fill(device_, pipelines[i], 300), expectedFill(300, 1.0f + float(i), i % 2 == 1)) << "pipeline " << i;
}

TEST_F(PipelineCacheTest, ABatchFailsWithTheFirstFailingDescriptorsError) {
  ShaderModule shader = module("fill", test_spirv::specialized_fill);
  std::vector<ComputePipelineDescriptor> descriptors{{"good", nullptr, &shader, "main", {}},
                                                     {"unknown constant", nullptr, &shader, "main", {{"kNone", 1}}},
                                                     {"no entry", nullptr, &shader, "other", {}}};
  EXPECT_THAT(errorOf([&] { device_.createComputePipelines(descriptors, 3); }),
              ::testing::AllOf(::testing::HasSubstr("'unknown constant'"), ::testing::HasSubstr("kNone")));
}

}  // namespace
}  // namespace facet::gpu::testing

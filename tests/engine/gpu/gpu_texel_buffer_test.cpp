// Texel buffers: uniform (texelFetch) and storage (imageLoad/imageStore)
// bindings through buffer views that the bind group makes.
#include <algorithm>
#include <bit>
#include <climits>
#include <random>

#include "engine/gpu/spirv_reflect.h"
#include "engine/gpu/vk_state.h"
#include "facet_test_kernels/spirv.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr std::uint64_t kTexel = 16;

// texel_gather.comp's order, over n texels.
std::uint32_t gathered(std::uint32_t i, std::uint32_t n) { return (i * 7919u + 13u) % n; }

const spirv::Binding& bindingOf(const spirv::Reflection& r, std::uint32_t binding) {
  auto it = std::find_if(r.bindings.begin(), r.bindings.end(), [&](const auto& b) { return b.binding == binding; });
  if (it == r.bindings.end()) throw std::runtime_error("no binding " + std::to_string(binding));
  return *it;
}

TEST_F(GpuTest, TexelFetchReturnsUintBitPatternsAndFloatsExactly) {
  const std::uint32_t n = 1000;  // texels, not a multiple of the workgroup size
  std::mt19937 rng(20240611);
  std::vector<std::uint32_t> patterns(4 * n);
  for (auto& p : patterns) p = rng();
  const std::uint32_t edges[] = {0xFFFFFFFFu, 0x80000001u, 0u, 0x7FFFFFFFu, 0x80000000u, 1u, 0x7F800001u, 0xFFC00000u};
  std::copy(std::begin(edges), std::end(edges), patterns.begin());
  std::uniform_real_distribution<float> range(-1000.0f, 1000.0f);
  std::vector<float> floats(4 * n);
  for (auto& f : floats) f = range(rng);
  floats[0] = -0.0f;
  floats[1] = 1.0e-30f;

  Buffer patternTexels = upload(patterns, BufferUsage::Texel);
  Buffer floatTexels = upload(floats, BufferUsage::Texel);
  Buffer out = poisoned(3 * n * kTexel);
  auto pipeline = derivedPipeline("texel read", test_spirv::texel_read);
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device_.createBindGroup(
      {"texel read", &layout, {{0, &patternTexels}, {1, &floatTexels}, {2, &floatTexels}, {3, &out}}});
  dispatchOnce(pipeline, group, (n + 63) / 64);
  auto result = readBack<std::uint32_t>(out);
  for (std::uint32_t i = 0; i < 4 * n; ++i) {
    const std::uint32_t texel = i / 4, component = i % 4, at = 12 * texel + component;
    ASSERT_EQ(result[at], patterns[i]) << "uint texel " << texel << ", component " << component;
    ASSERT_EQ(result[at + 4], std::bit_cast<std::uint32_t>(floats[i])) << "float texel " << texel;
    ASSERT_EQ(result[at + 8], std::bit_cast<std::uint32_t>(floats[i] * 2.0f + 1.0f)) << "uint-view texel " << texel;
  }
}

// The second dispatch reads, out of order, what the first wrote: it depends on
// the barrier the encoder inserts for a storage texel write.
TEST_F(GpuTest, StorageTexelWritesReachALaterDispatchInTheSameCommandBuffer) {
  const std::uint32_t n = 1 << 14;
  Buffer texels = poisoned(n * kTexel, BufferUsage::StorageTexel | BufferUsage::Texel);
  Buffer out = poisoned(n * kTexel);
  auto write = derivedPipeline("write", test_spirv::texel_write);
  auto gather = derivedPipeline("gather", test_spirv::texel_gather);
  auto writeLayout = write.getBindGroupLayout(0);
  auto gatherLayout = gather.getBindGroupLayout(0);
  auto writeGroup = device_.createBindGroup({"write", &writeLayout, {{0, &texels}}});
  auto gatherGroup = device_.createBindGroup({"gather", &gatherLayout, {{0, &texels}, {1, &out}}});
  auto encoder = device_.createCommandEncoder();
  const detail::CommandRecording& recording = *encoder.state();
  {
    auto pass = encoder.beginComputePass();
    pass.setPipeline(write);
    pass.setBindGroup(0, writeGroup);
    pass.dispatchWorkgroups(n / 64);
    EXPECT_EQ(recording.writtenSinceBarrier.count(texels.state().get()), 1u);
    pass.setPipeline(gather);
    pass.setBindGroup(0, gatherGroup);
    pass.dispatchWorkgroups(n / 64);
    EXPECT_EQ(recording.writtenSinceBarrier.count(texels.state().get()), 0u) << "no barrier after the write";
    EXPECT_EQ(recording.readSinceBarrier.count(texels.state().get()), 1u);
  }
  device_.queue().submit(encoder.finish());
  auto result = readBack<std::uint32_t>(out);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = gathered(i, n);
    const std::uint32_t expected[4] = {j * 2654435761u, ~j, j ^ 0x80000001u, 0xFFFFFFFFu};
    for (int c = 0; c < 4; ++c) ASSERT_EQ(result[4 * i + c], expected[c]) << "texel " << i << ", component " << c;
  }
}

TEST_F(GpuTest, TexelBindingAtANonZeroAlignedOffset) {
  const std::uint64_t offset = std::max<std::uint64_t>(device_.limits().minTexelBufferOffsetAlignment, kTexel);
  const std::uint32_t skipped = std::uint32_t(offset / kTexel), bound = 100;
  std::vector<std::uint32_t> values(4 * (skipped + bound + 7));
  for (std::uint32_t i = 0; i < values.size(); ++i) values[i] = i * 0x9E3779B9u;
  Buffer texels = upload(values, BufferUsage::Texel);
  Buffer out = poisoned(bound * kTexel);
  auto pipeline = derivedPipeline("gather", test_spirv::texel_gather);
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device_.createBindGroup({"offset", &layout, {{0, &texels, offset, bound * kTexel}, {1, &out}}});
  dispatchOnce(pipeline, group, (bound + 63) / 64);
  auto result = readBack<std::uint32_t>(out);
  for (std::uint32_t i = 0; i < bound; ++i) {
    for (std::uint32_t c = 0; c < 4; ++c)
      ASSERT_EQ(result[4 * i + c], values[4 * (skipped + gathered(i, bound)) + c]) << "texel " << i;
  }
}

// A read-only storage texel buffer is a read for hazard tracking, though its
// type (unlike storage buffers') does not say so.
TEST_F(GpuTest, ReadOnlyStorageTexelAndSamplerlessTextureBuffers) {
  const std::uint32_t n = 300;
  std::vector<std::int32_t> ints(4 * n);
  std::vector<float> floats(4 * n);
  for (std::uint32_t i = 0; i < 4 * n; ++i) {
    ints[i] = std::int32_t(i * 2654435761u);
    floats[i] = float(int(i % 2000) - 1000);
  }
  ints[0] = INT_MIN;
  ints[1] = -1;
  ints[2] = INT_MAX;
  Buffer signedTexels = upload(ints, BufferUsage::StorageTexel);
  Buffer floatTexels = upload(floats, BufferUsage::Texel);
  Buffer out = poisoned(n * kTexel);
  auto pipeline = derivedPipeline("load", test_spirv::texel_load);
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device_.createBindGroup({"load", &layout, {{0, &signedTexels}, {1, &floatTexels}, {2, &out}}});
  auto encoder = device_.createCommandEncoder();
  {
    auto pass = encoder.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups((n + 63) / 64);
  }
  EXPECT_EQ(encoder.state()->readSinceBarrier.count(signedTexels.state().get()), 1u);
  EXPECT_EQ(encoder.state()->writtenSinceBarrier.count(signedTexels.state().get()), 0u);
  device_.queue().submit(encoder.finish());
  auto result = readBack<std::int32_t>(out);
  for (std::uint32_t i = 0; i < 4 * n; ++i)
    ASSERT_EQ(result[i], std::int32_t(std::uint32_t(ints[i]) - std::uint32_t(std::int32_t(floats[i])))) << i;
}

TEST_F(GpuTest, ReflectionAndDerivedLayoutsKnowTexelTypesAndFormats) {
  auto read = spirv::reflect(test_spirv::texel_read, "texel_read");
  auto write = spirv::reflect(test_spirv::texel_write, "texel_write");
  auto load = spirv::reflect(test_spirv::texel_load, "texel_load");
  struct Expected {
    const spirv::Binding& binding;
    BindingType type;
    TexelFormat format;
    bool written;
  };
  for (const Expected& e :
       {Expected{bindingOf(read, 0), BindingType::TexelBuffer, TexelFormat::Rgba32Uint, false},
        Expected{bindingOf(read, 1), BindingType::TexelBuffer, TexelFormat::Rgba32Float, false},
        Expected{bindingOf(write, 0), BindingType::StorageTexelBuffer, TexelFormat::Rgba32Uint, true},
        Expected{bindingOf(load, 0), BindingType::StorageTexelBuffer, TexelFormat::Rgba32Sint, false},
        Expected{bindingOf(load, 1), BindingType::TexelBuffer, TexelFormat::Rgba32Float, false}}) {
    SCOPED_TRACE(e.binding.name);
    EXPECT_EQ(e.binding.type, e.type);
    EXPECT_EQ(e.binding.texelFormat, e.format);
    EXPECT_EQ(e.binding.written, e.written);
    EXPECT_EQ(e.binding.minSize, kTexel);
  }
  EXPECT_TRUE(bindingOf(read, 3).written);  // a writeonly storage buffer

  auto pipeline = derivedPipeline("load", test_spirv::texel_load);
  auto layout = pipeline.getBindGroupLayout(0);
  const auto& entries = layout.entries();
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].type, BindingType::StorageTexelBuffer);
  EXPECT_EQ(entries[0].texelFormat, TexelFormat::Rgba32Sint);
  EXPECT_EQ(entries[1].type, BindingType::TexelBuffer);
  EXPECT_EQ(entries[1].texelFormat, TexelFormat::Rgba32Float);
  EXPECT_EQ(entries[1].minBindingSize, kTexel);
}

class TexelMisuse : public PipelineTest {
 protected:
  void SetUp() override {
    PipelineTest::SetUp();
    setUpPipeline("gather", "texel_gather", test_spirv::texel_gather);
    out_ = device_.createBuffer({"out", 4096, BufferUsage::Storage});
    texels_ = device_.createBuffer({"texels", 4096, BufferUsage::Texel});
  }
  Buffer out_;
  Buffer texels_;
};

TEST_F(TexelMisuse, BufferWithoutTheTexelUsage) {
  Buffer storage = device_.createBuffer({"storage only", 4096, BufferUsage::Storage});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"gather", &layout_, {{0, &storage}, {1, &out_}}});
              }),
              AllOf(HasSubstr("bind group 'gather', binding 0"), HasSubstr("texel buffer binding"),
                    HasSubstr("usage Texel"), HasSubstr("buffer 'storage only' has Storage")));
  auto write = derivedPipeline("write", test_spirv::texel_write);
  auto writeLayout = write.getBindGroupLayout(0);
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"write", &writeLayout, {{0, &texels_}}});
              }),
              AllOf(HasSubstr("bind group 'write', binding 0"), HasSubstr("storage texel buffer binding"),
                    HasSubstr("usage StorageTexel"), HasSubstr("buffer 'texels' has Texel")));
}

TEST_F(TexelMisuse, SizeNotAWholeNumberOfTexels) {
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"ragged", &layout_, {{0, &texels_, 0, 20}, {1, &out_}}});
              }),
              AllOf(HasSubstr("bind group 'ragged', binding 0"), HasSubstr("multiple of 16")));
  Buffer ragged = device_.createBuffer({"ragged", 4100, BufferUsage::Texel});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"whole", &layout_, {{0, &ragged}, {1, &out_}}});
              }),
              AllOf(HasSubstr("bind group 'whole', binding 0"), HasSubstr("multiple of 16")));
}

// An offset off the device's texel alignment is an error; where every offset
// is aligned, one that is not a whole texel still binds (the texel size rule
// is the size's, not the offset's).
TEST_F(TexelMisuse, MisalignedOffset) {
  const std::uint32_t alignment = device_.limits().minTexelBufferOffsetAlignment;
  if (alignment == 1) {
    EXPECT_NO_THROW(device_.createBindGroup({"unaligned", &layout_, {{0, &texels_, 4, 64}, {1, &out_}}}));
    return;
  }
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"misaligned", &layout_, {{0, &texels_, alignment / 2, 64}, {1, &out_}}});
              }),
              AllOf(HasSubstr("bind group 'misaligned', binding 0"),
                    HasSubstr("offset " + std::to_string(alignment / 2) + " is not a multiple of " +
                              std::to_string(alignment))));
}

// Texel bindings are limited by maxTexelBufferElements, not by the storage
// binding size: a range the storage binding rejects binds as texels.
TEST_F(TexelMisuse, TexelBindingBeyondTheStorageBindingLimit) {
  const Limits& limits = device_.limits();
  const std::uint64_t size = limits.maxStorageBufferBindingSize + kTexel;
  if (size / kTexel > limits.maxTexelBufferElements || size > (std::uint64_t(256) << 20) || size > limits.maxBufferSize)
    GTEST_SKIP() << "maxStorageBufferBindingSize " << limits.maxStorageBufferBindingSize
                 << " is not below the texel limit, or too large to allocate here";
  Buffer big = device_.createBuffer({"big", size / kTexel * kTexel, BufferUsage::Texel});
  EXPECT_NO_THROW(device_.createBindGroup({"big", &layout_, {{0, &big}, {1, &out_}}}));
}

TEST_F(TexelMisuse, ExplicitLayoutThatDisagreesWithTheShader) {
  auto pipelineWith = [&](const BindGroupLayoutEntry& texel) {
    auto group = device_.createBindGroupLayout({"explicit", {texel, {1, BindingType::Storage}}});
    auto layout = device_.createPipelineLayout({"explicit", {&group}});
    return errorOf([&] { device_.createComputePipeline({"gather", &layout, &shader_}); });
  };
  EXPECT_THAT(pipelineWith({0, BindingType::TexelBuffer, 0, TexelFormat::Rgba32Float}),
              AllOf(HasSubstr("compute pipeline 'gather'"), HasSubstr("binding 0, 'source'"),
                    HasSubstr("is rgba32uint in the shader but rgba32float in bind group layout 'explicit'")));
  EXPECT_THAT(pipelineWith({0, BindingType::StorageTexelBuffer, 0, TexelFormat::Rgba32Uint}),
              HasSubstr("is texel buffer in the shader but storage texel buffer in bind group layout 'explicit'"));
  EXPECT_THAT(pipelineWith({0, BindingType::ReadOnlyStorage}),
              HasSubstr("is texel buffer in the shader but read-only storage in bind group layout 'explicit'"));
  EXPECT_EQ(pipelineWith({0, BindingType::TexelBuffer, 0, TexelFormat::Rgba32Uint}), "(no error)");
}

TEST_F(TexelMisuse, BindGroupMadeForAnotherTexelFormat) {
  auto floatLayout = device_.createBindGroupLayout(
      {"float texels", {{0, BindingType::TexelBuffer, 0, TexelFormat::Rgba32Float}, {1, BindingType::Storage}}});
  auto group = device_.createBindGroup({"float texels", &floatLayout, {{0, &texels_}, {1, &out_}}});
  EXPECT_THAT(bindGroupError(pipeline_, group),
              AllOf(HasSubstr("bind group 'float texels'"), HasSubstr("does not match group 0")));
}

TEST_F(TexelMisuse, NarrowFormatsAndArraysOfTexelBuffersAreNotSupported) {
  expectModuleRefused("texel_narrow", test_spirv::texel_narrow, "binding 0, 'narrow'", "only 4 x 32-bit texel formats");
  expectModuleRefused("texel_buffer_array", test_spirv::texel_buffer_array, "binding 0, 'tables'", "one per binding");
}

TEST(TexelBufferNames, UsagesTypesAndFormats) {
  EXPECT_EQ(toString(BufferUsage::Texel | BufferUsage::StorageTexel | BufferUsage::CopyDst),
            "CopyDst|Texel|StorageTexel");
  EXPECT_STREQ(toString(BindingType::TexelBuffer), "texel buffer");
  EXPECT_STREQ(toString(BindingType::StorageTexelBuffer), "storage texel buffer");
  EXPECT_STREQ(toString(TexelFormat::Rgba32Sint), "rgba32sint");
}

}  // namespace
}  // namespace facet::gpu::testing

// Kernels dispatched through the API: float math against the host,
// specialization constants, and dispatches that read each other's writes.
#include <bit>
#include <cmath>
#include <random>

#include "facet_test_kernels/spirv.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

// The same expression as well_conditioned_math.comp, in float, unfused
// (the project builds with -ffp-contract=off).
float hostMath(float a, float b, float c, float d) {
  float horner = ((((0.5f * c + 1.25f) * c + 0.75f) * c + 2.0f) * c + 0.125f) * c + 3.0f;
  return std::sqrt(a * a + b * b) + a / (1.0f + b) + horner * (1.0f / std::sqrt(d));
}

std::int64_t ulpDistance(float a, float b) {
  return std::abs(std::int64_t(std::bit_cast<std::int32_t>(a)) - std::int64_t(std::bit_cast<std::int32_t>(b)));
}

TEST_F(GpuTest, NonTrivialMathMatchesTheHostElementByElement) {
  const std::size_t n = 100'003;  // not a multiple of the workgroup size
  std::mt19937 rng(std::random_device{}());
  std::uniform_real_distribution<float> positive(0.01f, 10.0f);
  std::vector<float> inputs(4 * n);
  for (auto& x : inputs) x = positive(rng);

  Buffer in = upload(inputs);
  Buffer out = poisoned(n * sizeof(float));
  auto pipeline = derivedPipeline("math", test_spirv::well_conditioned_math);
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device_.createBindGroup({"math", &layout, {{0, &in}, {1, &out}}});
  dispatchOnce(pipeline, group, std::uint32_t((n + 63) / 64));
  auto result = readBack<float>(out);

  // Tolerance: 4 ULP. Every operation here is correctly rounded on lavapipe;
  // the margin admits hardware GPUs' inversesqrt.
  std::int64_t worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    float expected = hostMath(inputs[4 * i], inputs[4 * i + 1], inputs[4 * i + 2], inputs[4 * i + 3]);
    ASSERT_TRUE(std::isfinite(result[i])) << "element " << i << " was not written";
    worst = std::max(worst, ulpDistance(result[i], expected));
    ASSERT_LE(ulpDistance(result[i], expected), 4) << "element " << i << ": " << result[i] << " vs " << expected;
  }
  RecordProperty("worst_ulp", int(worst));
}

struct FillCase {
  int mode;
  float scale;
  bool negate;
  std::uint32_t workgroup;
};

class SpecializationConstants : public GpuTest, public ::testing::WithParamInterface<FillCase> {};

TEST_P(SpecializationConstants, ChangeTheResultAndTheWorkgroupSize) {
  const FillCase c = GetParam();
  const std::uint32_t n = 1000;
  Buffer out = poisoned(n * sizeof(float));
  auto pipeline = derivedPipeline(
      "fill", test_spirv::specialized_fill,
      {{"kMode", double(c.mode)}, {"kScale", c.scale}, {"kNegate", double(c.negate)}, {"0", double(c.workgroup)}});
  EXPECT_EQ(pipeline.workgroupSize()[0], c.workgroup);
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device_.createBindGroup({"fill", &layout, {{0, &out}}});
  dispatchOnce(pipeline, group, (n + c.workgroup - 1) / c.workgroup);
  auto values = readBack<float>(out);
  for (std::uint32_t i = 0; i < n; ++i) {
    float v = c.mode == 0 ? float(i) * c.scale : float(i * i) + c.scale;
    ASSERT_EQ(values[i], c.negate ? -v : v) << "element " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, SpecializationConstants,
                         ::testing::Values(FillCase{0, 1.0f, false, 64}, FillCase{0, 2.5f, true, 32},
                                           FillCase{1, 3.0f, false, 128}, FillCase{1, -1.0f, true, 1}),
                         [](const auto& info) {
                           const FillCase& c = info.param;
                           return "mode" + std::to_string(c.mode) + (c.negate ? "_negated" : "") + "_workgroup" +
                                  std::to_string(c.workgroup);
                         });

// Dispatch 1 writes data and dispatch 2's size; dispatch 2 runs indirectly and
// reads across workgroups: both depend on barriers the encoder inserts.
TEST_F(GpuTest, ChainedDispatchesInOneCommandBufferSeeEachOthersWrites) {
  const std::uint32_t n = 1 << 16;
  Buffer produced = poisoned(n * 4);
  Buffer consumed = poisoned(n * 4);
  Buffer indirect =
      device_.createBuffer({"indirect", 12, BufferUsage::Storage | BufferUsage::Indirect | BufferUsage::CopyDst});
  device_.queue().writeBuffer(indirect, 0, std::span<const std::uint32_t>(std::vector<std::uint32_t>{0, 0, 0}));
  auto produce = derivedPipeline("produce", test_spirv::chain_produce);
  auto consume = derivedPipeline("consume", test_spirv::chain_consume);
  auto produceLayout = produce.getBindGroupLayout(0);
  auto consumeLayout = consume.getBindGroupLayout(0);
  auto produceGroup = device_.createBindGroup({"produce", &produceLayout, {{0, &produced}, {1, &indirect}}});
  auto consumeGroup = device_.createBindGroup({"consume", &consumeLayout, {{0, &produced}, {1, &consumed}}});
  auto encoder = device_.createCommandEncoder();
  {
    auto pass = encoder.beginComputePass();
    pass.setPipeline(produce);
    pass.setBindGroup(0, produceGroup);
    pass.dispatchWorkgroups(n / 64);
    pass.setPipeline(consume);
    pass.setBindGroup(0, consumeGroup);
    pass.dispatchWorkgroupsIndirect(indirect);
  }
  device_.queue().submit(encoder.finish());
  auto out = readBack<std::uint32_t>(consumed);
  auto value = [](std::uint32_t i) { return i * 2654435761u; };
  for (std::uint32_t i = 0; i < n; ++i)
    ASSERT_EQ(out[i], value((i * 7919u + 13u) % n) ^ value(n - 1 - i)) << "element " << i;
}

}  // namespace
}  // namespace facet::gpu::testing

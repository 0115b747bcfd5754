// Every misuse raises facet::gpu::Error naming the object and the rule, before
// Vulkan sees it: the fixture also fails on any validation message.
#include <cstdlib>

#include "facet_test_kernels/spirv.h"
#include "gpu_test.h"

namespace facet::gpu::testing {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

class Misuse : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    shader_ = module("specialized_fill", test_spirv::specialized_fill);
    pipeline_ = device_.createComputePipeline({"fill", nullptr, &shader_, "main", {{"0", 64}}});
    layout_ = pipeline_.getBindGroupLayout(0);
    storage_ = device_.createBuffer({"values", 4096, BufferUsage::Storage | BufferUsage::CopyDst});
    group_ = device_.createBindGroup({"fill", &layout_, {{0, &storage_}}});
  }
  ShaderModule shader_;
  ComputePipeline pipeline_;
  BindGroupLayout layout_;
  Buffer storage_;
  BindGroup group_;
};

TEST_F(Misuse, BindingABufferWithoutStorageUsageToAStorageBinding) {
  Buffer uniform = device_.createBuffer({"params", 256, BufferUsage::Uniform});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"fill", &layout_, {{0, &uniform}}});
              }),
              AllOf(HasSubstr("bind group 'fill'"), HasSubstr("buffer 'params'"), HasSubstr("usage Storage")));
}

TEST_F(Misuse, BindingIndexNotInTheLayout) {
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"fill", &layout_, {{0, &storage_}, {7, &storage_}}});
              }),
              AllOf(HasSubstr("binding 7"), HasSubstr("not in"), HasSubstr("it has 0")));
}

TEST_F(Misuse, LayoutBindingLeftUnbound) {
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"empty", &layout_, {}});
              }),
              AllOf(HasSubstr("bind group 'empty'"), HasSubstr("binding 0"), HasSubstr("has no buffer")));
}

TEST_F(Misuse, BuffersTooSmallForTheShadersBlocks) {
  auto shader = module("fixed_block", test_spirv::fixed_block);
  auto pipeline = device_.createComputePipeline({"fixed", nullptr, &shader});
  auto layout = pipeline.getBindGroupLayout(0);
  // std140 mat4 + vec4 = 80 bytes; std430 vec4[4] + one float = 68 bytes.
  Buffer params79 = device_.createBuffer({"params79", 79, BufferUsage::Uniform});
  Buffer params80 = device_.createBuffer({"params80", 80, BufferUsage::Uniform});
  Buffer output64 = device_.createBuffer({"output64", 64, BufferUsage::Storage});
  Buffer output68 = device_.createBuffer({"output68", 68, BufferUsage::Storage});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"small", &layout, {{0, &params79}, {1, &output68}}});
              }),
              AllOf(HasSubstr("buffer 'params79' is too small"), HasSubstr("79 bytes bound"), HasSubstr("80 needed")));
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"small", &layout, {{0, &params80}, {1, &output64}}});
              }),
              AllOf(HasSubstr("buffer 'output64' is too small"), HasSubstr("68 needed")));
  EXPECT_NO_THROW(device_.createBindGroup({"exact", &layout, {{0, &params80}, {1, &output68}}}));
}

TEST_F(Misuse, BindingMoreThanMaxStorageBufferBindingSize) {
  const std::uint64_t max = device_.limits().maxStorageBufferBindingSize;
  Buffer big = device_.createBuffer({"big", max + 4096, BufferUsage::Storage});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"fill", &layout_, {{0, &big}}});
              }),
              AllOf(HasSubstr("buffer 'big'"), HasSubstr("maxStorageBufferBindingSize")));
  EXPECT_NO_THROW(device_.createBindGroup({"fill", &layout_, {{0, &big, 0, max}}}));
}

TEST_F(Misuse, BufferLargerThanTheDeviceAllows) {
  EXPECT_THAT(errorOf([&] {
                device_.createBuffer({"huge", device_.limits().maxBufferSize + 1, BufferUsage::Storage});
              }),
              AllOf(HasSubstr("buffer 'huge'"), HasSubstr("maxBufferSize")));
}

TEST_F(Misuse, DispatchBeyondTheWorkgroupCountLimit) {
  auto encoder = device_.createCommandEncoder();
  auto pass = encoder.beginComputePass({"too big"});
  pass.setPipeline(pipeline_);
  pass.setBindGroup(0, group_);
  const std::uint32_t over = device_.limits().maxComputeWorkgroupsPerDimension[0] + 1;
  EXPECT_THAT(errorOf([&] { pass.dispatchWorkgroups(over); }),
              AllOf(HasSubstr("compute pass 'too big'"), HasSubstr("maxComputeWorkgroupsPerDimension")));
}

TEST_F(Misuse, DispatchWithoutPipelineOrBindGroup) {
  auto encoder = device_.createCommandEncoder();
  auto pass = encoder.beginComputePass({"incomplete"});
  EXPECT_THAT(errorOf([&] { pass.dispatchWorkgroups(1); }), HasSubstr("without setPipeline"));
  pass.setPipeline(pipeline_);
  EXPECT_THAT(errorOf([&] { pass.dispatchWorkgroups(1); }), AllOf(HasSubstr("bind group 0"), HasSubstr("not set")));
}

TEST_F(Misuse, BindGroupMadeForAnotherLayout) {
  auto shader = module("fixed_block", test_spirv::fixed_block);
  auto other = device_.createComputePipeline({"fixed", nullptr, &shader});
  auto encoder = device_.createCommandEncoder();
  auto pass = encoder.beginComputePass();
  pass.setPipeline(other);
  EXPECT_THAT(errorOf([&] { pass.setBindGroup(0, group_); }),
              AllOf(HasSubstr("bind group 'fill'"), HasSubstr("does not match group 0")));
}

TEST_F(Misuse, ExplicitLayoutThatDisagreesWithTheShader) {
  auto readOnly = device_.createBindGroupLayout({"read only", {{0, BindingType::ReadOnlyStorage}}});
  auto empty = device_.createBindGroupLayout({"empty", {}});
  auto readOnlyLayout = device_.createPipelineLayout({"ro", {&readOnly}});
  auto emptyLayout = device_.createPipelineLayout({"none", {&empty}});
  EXPECT_THAT(errorOf([&] {
                device_.createComputePipeline({"fill", &readOnlyLayout, &shader_, "main", {{"0", 64}}});
              }),
              AllOf(HasSubstr("is storage in the shader but read-only storage")));
  EXPECT_THAT(errorOf([&] {
                device_.createComputePipeline({"fill", &emptyLayout, &shader_, "main", {{"0", 64}}});
              }),
              AllOf(HasSubstr("binding 0"), HasSubstr("missing from bind group layout 'empty'")));
}

TEST_F(Misuse, UnknownOrInvalidPipelineConstants) {
  EXPECT_THAT(errorOf([&] {
                device_.createComputePipeline({"fill", nullptr, &shader_, "main", {{"kModes", 1}}});
              }),
              AllOf(HasSubstr("no overridable constant 'kModes'"), HasSubstr("kMode")));
  EXPECT_THAT(errorOf([&] {
                device_.createComputePipeline({"fill", nullptr, &shader_, "main", {{"kMode", 1.5}}});
              }),
              HasSubstr("integral"));
  EXPECT_THAT(errorOf([&] {
                device_.createComputePipeline({"fill", nullptr, &shader_, "main", {{"0", 4096}}});
              }),
              HasSubstr("workgroup size 4096"));
  EXPECT_THAT(errorOf([&] {
                device_.createComputePipeline({"fill", nullptr, &shader_, "nope"});
              }),
              HasSubstr("no compute entry point 'nope'"));
}

TEST_F(Misuse, PushConstantsAreNotPartOfTheApi) {
  auto shader = module("push_constants", test_spirv::push_constants);
  EXPECT_THAT(
      errorOf([&] {
        device_.createComputePipeline({"push", nullptr, &shader});
      }),
      AllOf(HasSubstr("shader module 'push_constants'"), HasSubstr("push constants"), HasSubstr("uniform buffer")));
}

TEST_F(Misuse, NotSpirv) {
  std::vector<std::uint32_t> garbage{0xdeadbeef, 1, 2, 3, 4, 5};
  EXPECT_THAT(errorOf([&] {
                device_.createShaderModule({"garbage", garbage});
              }),
              AllOf(HasSubstr("shader module 'garbage'"), HasSubstr("not a SPIR-V module")));
}

TEST_F(Misuse, BufferUsageRules) {
  EXPECT_THAT(errorOf([&] {
                device_.createBuffer({"both", 64, BufferUsage::MapRead | BufferUsage::Storage});
              }),
              HasSubstr("MapRead may only be combined with CopyDst"));
  EXPECT_THAT(errorOf([&] {
                device_.queue().writeBuffer(device_.createBuffer({"no copy", 64, BufferUsage::Storage}), 0, "abcd", 4);
              }),
              HasSubstr("needs usage CopyDst"));
  EXPECT_THAT(errorOf([&] { storage_.mappedRange(); }), HasSubstr("needs usage MapRead or MapWrite"));
  EXPECT_THAT(errorOf([&] { device_.queue().writeBuffer(storage_, 4096, "abcd", 4); }), HasSubstr("exceeds the size"));
}

TEST_F(Misuse, EncoderOrderRules) {
  auto encoder = device_.createCommandEncoder({"enc"});
  {
    auto pass = encoder.beginComputePass({"open"});
    EXPECT_THAT(errorOf([&] { encoder.finish(); }), HasSubstr("compute pass 'open' is open"));
  }
  auto commands = encoder.finish();
  device_.queue().submit(std::move(commands));
  EXPECT_THAT(errorOf([&] { device_.queue().submit(std::move(commands)); }), HasSubstr("already submitted"));
}

TEST(NoDriver, InstanceCreationExplainsWhatToInstall) {
  const char* previous = std::getenv("VK_DRIVER_FILES");
  std::string saved = previous ? previous : "";
  setenv("VK_DRIVER_FILES", "/nonexistent/facet_icd.json", 1);
  std::string message = errorOf([] { Instance::create(); });
  previous ? setenv("VK_DRIVER_FILES", saved.c_str(), 1) : unsetenv("VK_DRIVER_FILES");
  EXPECT_THAT(message, AllOf(HasSubstr("no Vulkan driver found"), HasSubstr("mesa-vulkan-drivers")));
}

}  // namespace
}  // namespace facet::gpu::testing

// Every misuse raises facet::gpu::Error naming the object and the rule, before
// Vulkan sees it: the fixture also fails on any validation message.
#include <cstdlib>
#include <type_traits>

#include "facet_test_kernels/spirv.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

class Misuse : public PipelineTest {
 protected:
  void SetUp() override {
    PipelineTest::SetUp();
    setUpPipeline("fill", "specialized_fill", test_spirv::specialized_fill, {{"0", 64}});
    storage_ = device_.createBuffer({"values", 4096, BufferUsage::Storage | BufferUsage::CopyDst});
    group_ = device_.createBindGroup({"fill", &layout_, {{0, &storage_}}});
  }
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
  auto pipeline = derivedPipeline("fixed", test_spirv::fixed_block);
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
  auto other = derivedPipeline("fixed", test_spirv::fixed_block);
  EXPECT_THAT(bindGroupError(other, group_),
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

TEST_F(Misuse, BindGroupLeftBoundAcrossAPipelineWithAnotherLayout) {
  auto fixed = derivedPipeline("fixed", test_spirv::fixed_block);
  auto encoder = device_.createCommandEncoder();
  auto pass = encoder.beginComputePass({"switch"});
  pass.setPipeline(pipeline_);
  pass.setBindGroup(0, group_);
  pass.setPipeline(fixed);
  EXPECT_THAT(errorOf([&] { pass.dispatchWorkgroups(1); }),
              AllOf(HasSubstr("compute pass 'switch'"), HasSubstr("bind group 'fill' at group 0"),
                    HasSubstr("bind group layout 'fill group 0'"), HasSubstr("bind group layout 'fixed group 0'"),
                    HasSubstr("compute pipeline 'fixed'")));
}

// Group 1 is bound under pipeline layout A; binding group 0 under layout B,
// whose group 0 differs, disturbs it in Vulkan. Dispatch must bind it again
// with B (the fixture fails on the validation message otherwise).
TEST_F(Misuse, SwitchingPipelineLayoutsRebindsTheGroupsStillBound) {
  auto shader = module("two_groups", test_spirv::two_groups);
  auto outputsOnly = device_.createBindGroupLayout({"outputs only", {{0, BindingType::Storage}}});
  auto outputsAndSpare =
      device_.createBindGroupLayout({"outputs and spare", {{0, BindingType::Storage}, {1, BindingType::Storage}}});
  auto inputs = device_.createBindGroupLayout({"inputs", {{0, BindingType::ReadOnlyStorage}}});
  auto layoutA = device_.createPipelineLayout({"A", {&outputsOnly, &inputs}});
  auto layoutB = device_.createPipelineLayout({"B", {&outputsAndSpare, &inputs}});
  auto pipelineA = device_.createComputePipeline({"A", &layoutA, &shader});
  auto pipelineB = device_.createComputePipeline({"B", &layoutB, &shader});

  std::vector<std::uint32_t> values(64);
  for (std::uint32_t i = 0; i < values.size(); ++i) values[i] = i * 3;
  Buffer input = upload(values);
  Buffer output = poisoned(values.size() * sizeof(std::uint32_t));
  Buffer spare = device_.createBuffer({"spare", 256, BufferUsage::Storage});
  auto inputGroup = device_.createBindGroup({"inputs", &inputs, {{0, &input}}});
  auto outputGroup = device_.createBindGroup({"outputs", &outputsAndSpare, {{0, &output}, {1, &spare}}});

  auto encoder = device_.createCommandEncoder();
  {
    auto pass = encoder.beginComputePass({"switch"});
    pass.setPipeline(pipelineA);
    pass.setBindGroup(1, inputGroup);
    pass.setPipeline(pipelineB);
    pass.setBindGroup(0, outputGroup);
    pass.dispatchWorkgroups(1);
  }
  device_.queue().submit(encoder.finish());
  auto result = readBack<std::uint32_t>(output);
  for (std::uint32_t i = 0; i < values.size(); ++i) EXPECT_EQ(result[i], values[i] + 1) << "element " << i;
}

TEST_F(Misuse, WriteBufferRangeThatWrapsAround) {
  const std::uint64_t nearWrap = ~std::uint64_t(0) - 3;  // offset + 4 wraps to 0
  EXPECT_THAT(errorOf([&] { device_.queue().writeBuffer(storage_, nearWrap, "abcd", 4); }),
              AllOf(HasSubstr("buffer 'values'"), HasSubstr("exceeds the size 4096")));
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"wrap", &layout_, {{0, &storage_, 256, nearWrap - 252}}});
              }),
              AllOf(HasSubstr("bind group 'wrap'"), HasSubstr("exceeds buffer 'values'")));
}

TEST_F(Misuse, MovedFromHandlesAreErrors) {
  Buffer buffer = device_.createBuffer({"moved", 64, BufferUsage::Storage | BufferUsage::CopyDst});
  Buffer bufferTaken = std::move(buffer);
  EXPECT_THAT(errorOf([&] { buffer.size(); }), HasSubstr("buffer is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { device_.queue().writeBuffer(buffer, 0, "abcd", 4); }),
              HasSubstr("Queue::writeBuffer's buffer is moved-from or empty"));
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"fill", &layout_, {{0, &buffer}}});
              }),
              AllOf(HasSubstr("bind group 'fill'"), HasSubstr("moved-from or empty")));
  {
    auto encoder = device_.createCommandEncoder();
    EXPECT_THAT(errorOf([&] { encoder.copyBufferToBuffer(buffer, 0, storage_, 0, 4); }),
                HasSubstr("copyBufferToBuffer source buffer is moved-from or empty"));
    EXPECT_THAT(errorOf([&] { encoder.clearBuffer(buffer); }), HasSubstr("clearBuffer buffer is moved-from or empty"));
    CommandEncoder encoderTaken = std::move(encoder);
    EXPECT_THAT(errorOf([&] { encoder.finish(); }), HasSubstr("command encoder is moved-from or empty"));
    EXPECT_THAT(errorOf([&] { encoder.beginComputePass(); }), HasSubstr("command encoder is moved-from or empty"));
  }

  ComputePipeline pipeline = device_.createComputePipeline({"moved", nullptr, &shader_, "main", {{"0", 64}}});
  ComputePipeline pipelineTaken = std::move(pipeline);
  BindGroup group = device_.createBindGroup({"moved", &layout_, {{0, &storage_}}});
  BindGroup groupTaken = std::move(group);
  QuerySet queries = device_.createQuerySet({"moved", 2});
  QuerySet queriesTaken = std::move(queries);
  EXPECT_THAT(errorOf([&] { pipeline.getBindGroupLayout(0); }), HasSubstr("compute pipeline is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { pipeline.workgroupSize(); }), HasSubstr("compute pipeline is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { queries.count(); }), HasSubstr("query set is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { queries.readTimestampsNs(0, 1); }), HasSubstr("query set is moved-from or empty"));
  {
    auto encoder = device_.createCommandEncoder();
    EXPECT_THAT(errorOf([&] {
                  encoder.beginComputePass({"timed", {&queries, 0, 1}});
                }),
                HasSubstr("compute pass 'timed' timestamp query set is moved-from or empty"));
    auto pass = encoder.beginComputePass({"moved"});
    EXPECT_THAT(errorOf([&] { pass.setPipeline(pipeline); }),
                HasSubstr("compute pass 'moved': setPipeline's pipeline is moved-from or empty"));
    pass.setPipeline(pipeline_);
    EXPECT_THAT(errorOf([&] { pass.setBindGroup(0, group); }),
                HasSubstr("setBindGroup(0)'s bind group is moved-from or empty"));
    pass.setBindGroup(0, group_);
    EXPECT_THAT(errorOf([&] { pass.dispatchWorkgroupsIndirect(buffer); }),
                HasSubstr("dispatchWorkgroupsIndirect buffer is moved-from or empty"));
    ComputePassEncoder passTaken = std::move(pass);
    EXPECT_THAT(errorOf([&] { pass.dispatchWorkgroups(1); }), HasSubstr("compute pass encoder is moved-from or empty"));
    EXPECT_THAT(errorOf([&] { pass.end(); }), HasSubstr("compute pass encoder is moved-from or empty"));
  }

  Device device = instance_.requestAdapter().requestDevice({"moved"});
  Queue& queue = device.queue();
  Device deviceTaken = std::move(device);
  EXPECT_THAT(errorOf([&] {
                device.createBuffer({"b", 64, BufferUsage::Storage});
              }),
              HasSubstr("device is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { device.createCommandEncoder(); }), HasSubstr("device is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { device.queue(); }), HasSubstr("device is moved-from or empty"));
  EXPECT_THAT(errorOf([&] { queue.waitIdle(); }), HasSubstr("queue is moved-from or empty"));

  Instance instance = Instance::create();
  Instance instanceTaken = std::move(instance);
  EXPECT_THAT(errorOf([&] { instance.requestAdapter(); }), HasSubstr("instance is moved-from or empty"));
}

// A copied Queue could outlive or diverge from the Device that holds it.
static_assert(!std::is_copy_constructible_v<Queue> && !std::is_copy_assignable_v<Queue>);
static_assert(std::is_nothrow_move_constructible_v<Device> && std::is_nothrow_move_assignable_v<Device>);

TEST_F(Misuse, PassEncoderKeptAfterItsEnd) {
  auto encoder = device_.createCommandEncoder({"enc"});
  auto first = encoder.beginComputePass({"first"});
  first.end();
  auto second = encoder.beginComputePass({"second"});
  EXPECT_THAT(errorOf([&] { first.setPipeline(pipeline_); }), HasSubstr("used after its end()"));
  EXPECT_THAT(errorOf([&] { first.end(); }), HasSubstr("used after its end()"));
  second.setPipeline(pipeline_);  // the open pass is unaffected
}

TEST_F(Misuse, EncoderUsedAfterFinish) {
  auto encoder = device_.createCommandEncoder({"done"});
  auto commands = encoder.finish();
  EXPECT_THAT(errorOf([&] { encoder.beginComputePass(); }),
              AllOf(HasSubstr("command encoder 'done'"), HasSubstr("beginComputePass after finish()")));
  EXPECT_THAT(errorOf([&] { encoder.clearBuffer(storage_); }), HasSubstr("clearBuffer after finish()"));
  EXPECT_THAT(errorOf([&] { encoder.finish(); }), HasSubstr("finish after finish()"));
  device_.queue().submit(std::move(commands));
  EXPECT_THAT(errorOf([&] { encoder.copyBufferToBuffer(storage_, 0, storage_, 64, 4); }),
              HasSubstr("copyBufferToBuffer after finish()"));
}

TEST_F(Misuse, ImagesSamplersAndBufferArraysAreNotSupported) {
  expectModuleRefused("sampled_image", test_spirv::sampled_image, "binding 0, 'image'",
                      "only uniform, storage and texel buffers");
  expectModuleRefused("buffer_array", test_spirv::buffer_array, "binding 0, 'blocks'", "one buffer per binding");
}

TEST_F(Misuse, RowMajorMatrixBlockSize) {
  auto pipeline = derivedPipeline("row major", test_spirv::row_major_block);
  auto layout = pipeline.getBindGroupLayout(0);
  // row_major mat2x4 in std430: 4 rows of vec2 at an 8-byte stride.
  Buffer small = device_.createBuffer({"small", 28, BufferUsage::Storage});
  Buffer exact = device_.createBuffer({"exact", 32, BufferUsage::Storage});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"small", &layout, {{0, &small}}});
              }),
              AllOf(HasSubstr("buffer 'small' is too small"), HasSubstr("32 needed")));
  EXPECT_NO_THROW(device_.createBindGroup({"exact", &layout, {{0, &exact}}}));
}

TEST_F(Misuse, MapUsageWithoutItsCopyPartnerOrUnknownUsageBits) {
  EXPECT_THAT(errorOf([&] {
                device_.createBuffer({"read", 64, BufferUsage::MapRead});
              }),
              AllOf(HasSubstr("buffer 'read'"), HasSubstr("MapRead needs CopyDst")));
  EXPECT_THAT(errorOf([&] {
                device_.createBuffer({"write", 64, BufferUsage::MapWrite});
              }),
              AllOf(HasSubstr("buffer 'write'"), HasSubstr("MapWrite needs CopySrc")));
  EXPECT_THAT(errorOf([&] {
                device_.createBuffer({"unknown", 64, BufferUsage::Storage | BufferUsage(1u << 4)});
              }),
              AllOf(HasSubstr("buffer 'unknown'"), HasSubstr("unknown bits 0x10")));
}

TEST_F(Misuse, ZeroSizeBinding) {
  auto anySize = device_.createBindGroupLayout({"any size", {{0, BindingType::Storage, 0}}});
  EXPECT_THAT(errorOf([&] {
                device_.createBindGroup({"empty range", &anySize, {{0, &storage_, 0, 0}}});
              }),
              AllOf(HasSubstr("bind group 'empty range', binding 0"), HasSubstr("size must be greater than 0")));
}

// Hand-assembled modules: reflection reads them before Vulkan does, so each
// defect must be an Error naming the module rather than an exception from a
// container or a read past an instruction.
class SpirvWords {
 public:
  SpirvWords() : words_{0x07230203, 0x00010500, 0, 100, 0} {}
  SpirvWords& add(std::uint32_t op, const std::vector<std::uint32_t>& operands) {
    words_.push_back(std::uint32_t(operands.size() + 1) << 16 | op);
    words_.insert(words_.end(), operands.begin(), operands.end());
    return *this;
  }
  // A storage buffer variable %10 at binding 0 whose block %6 holds type %5.
  SpirvWords& bufferOf(std::uint32_t memberType) {
    return add(71, {10, 33, 0})    // OpDecorate %10 Binding 0
        .add(30, {6, memberType})  // OpTypeStruct %6
        .add(32, {7, 12, 6})       // OpTypePointer %7 StorageBuffer %6
        .add(59, {7, 10, 12});     // OpVariable %7 %10 StorageBuffer
  }
  std::span<const std::uint32_t> words() const { return words_; }

 private:
  std::vector<std::uint32_t> words_;
};

TEST_F(Misuse, MalformedOrUnsupportedSpirvNamesTheModule) {
  auto errorFor = [&](const char* label, const SpirvWords& spirv) {
    return errorOf([&] { device_.createShaderModule({label, spirv.words()}); });
  };
  // float %1, uint %2, OpSpecConstant %4 = 4, array %5 of %1 with length %3.
  auto arrayWithLength = [](std::uint32_t lengthOp, const std::vector<std::uint32_t>& lengthOperands) {
    SpirvWords spirv;
    spirv.add(22, {1, 32}).add(21, {2, 32, 0}).add(50, {2, 4, 4}).add(lengthOp, lengthOperands).add(28, {5, 1, 3});
    spirv.bufferOf(5);
    return spirv;
  };
  EXPECT_THAT(errorFor("spec op length", arrayWithLength(52, {2, 3, 128, 4, 4})),  // OpSpecConstantOp IAdd
              AllOf(HasSubstr("shader module 'spec op length'"), HasSubstr("array length %3"),
                    HasSubstr("not a literal constant")));
  EXPECT_THAT(errorFor("null length", arrayWithLength(46, {2, 3})),  // OpConstantNull
              AllOf(HasSubstr("shader module 'null length'"), HasSubstr("array length %3")));
  EXPECT_THAT(errorFor("short int", SpirvWords().add(21, {2})),  // OpTypeInt without width or signedness
              AllOf(HasSubstr("shader module 'short int'"), HasSubstr("malformed instruction (opcode 21")));
  EXPECT_THAT(errorFor("short binding", SpirvWords().add(71, {10, 33})),  // OpDecorate Binding without a number
              AllOf(HasSubstr("shader module 'short binding'"), HasSubstr("malformed instruction (opcode 71")));
  EXPECT_THAT(errorFor("undefined type", SpirvWords().bufferOf(99)),
              AllOf(HasSubstr("shader module 'undefined type'"), HasSubstr("%99 is not a type")));
  EXPECT_THAT(errorFor("self nesting", SpirvWords().add(30, {5, 5}).bufferOf(5)),
              AllOf(HasSubstr("shader module 'self nesting'"), HasSubstr("nests too deeply")));
  EXPECT_THAT(errorFor("local size id", SpirvWords().add(331, {1, 38, 4, 4, 4})),  // OpExecutionModeId LocalSizeId
              AllOf(HasSubstr("shader module 'local size id'"), HasSubstr("LocalSizeId"), HasSubstr("maintenance4")));
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

// Shared fixture: a device on the default adapter with Vulkan validation on
// when installed. Any validation message fails the test that caused it.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"

namespace facet::gpu::testing {

// The message of the Error that `f` raises.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override {
    instance_ = Instance::create({Validation::IfInstalled});
    device_ = instance_.requestAdapter().requestDevice({"test device"});
  }

  void TearDown() override {
    device_.queue().waitIdle();
    device_ = Device();
    for (const auto& message : instance_.takeValidationMessages()) ADD_FAILURE() << "Vulkan validation: " << message;
  }

  template <class T>
  Buffer upload(const std::vector<T>& data, BufferUsage usage = BufferUsage::Storage) {
    Buffer buffer = device_.createBuffer({"upload", data.size() * sizeof(T), usage | BufferUsage::CopyDst});
    device_.queue().writeBuffer(buffer, 0, std::span<const T>(data));
    return buffer;
  }

  // Fills a storage buffer with a poison byte pattern, so elements a kernel
  // fails to write are caught (0xFF bytes read as NaN for floats).
  Buffer poisoned(std::uint64_t bytes, BufferUsage usage = BufferUsage::Storage) {
    return upload(std::vector<std::uint8_t>(bytes, 0xFF), usage | BufferUsage::CopySrc);
  }

  template <class T>
  std::vector<T> readBack(const Buffer& buffer) {
    Buffer staging = device_.createBuffer({"readback", buffer.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
    auto encoder = device_.createCommandEncoder({"readback"});
    encoder.copyBufferToBuffer(buffer, 0, staging, 0, buffer.size());
    device_.queue().submit(encoder.finish());
    device_.queue().waitIdle();
    auto bytes = staging.mappedRange();
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
  }

  // One compute pass with one dispatch, submitted (readBack waits for it).
  void dispatchOnce(const ComputePipeline& pipeline, const BindGroup& group, std::uint32_t workgroups) {
    auto encoder = device_.createCommandEncoder();
    {
      auto pass = encoder.beginComputePass();
      pass.setPipeline(pipeline);
      pass.setBindGroup(0, group);
      pass.dispatchWorkgroups(workgroups);
    }
    device_.queue().submit(encoder.finish());
  }

  ShaderModule module(const char* label, std::span<const std::uint32_t> code) {
    return device_.createShaderModule({label, code});
  }

  // A pipeline on the kernel's "main", with its layout derived from the shader.
  ComputePipeline derivedPipeline(const char* label, std::span<const std::uint32_t> code,
                                  std::vector<ConstantEntry> constants = {}) {
    ShaderModule shader = module(label, code);
    return device_.createComputePipeline({label, nullptr, &shader, "main", std::move(constants)});
  }

  // Expects the kernel to be refused when its module is created, with an
  // error that names the module, the binding and the reason.
  void expectModuleRefused(const char* label, std::span<const std::uint32_t> code, const std::string& binding,
                           const std::string& reason) {
    EXPECT_THAT(errorOf([&] { module(label, code); }),
                ::testing::AllOf(::testing::HasSubstr(std::string("shader module '") + label + "'"),
                                 ::testing::HasSubstr(binding), ::testing::HasSubstr(reason)));
  }

  // The error of binding `group` at group 0 of a pass set to `pipeline`.
  std::string bindGroupError(const ComputePipeline& pipeline, const BindGroup& group) {
    auto encoder = device_.createCommandEncoder();
    auto pass = encoder.beginComputePass();
    pass.setPipeline(pipeline);
    return errorOf([&] { pass.setBindGroup(0, group); });
  }

  Instance instance_;
  Device device_;
};

// A device and one pipeline on a kernel's "main": the module stays for tests
// that build other pipelines from it, the group-0 layout for bind groups.
class PipelineTest : public GpuTest {
 protected:
  void setUpPipeline(const char* label, const char* moduleLabel, std::span<const std::uint32_t> code,
                     std::vector<ConstantEntry> constants = {}) {
    shader_ = module(moduleLabel, code);
    pipeline_ = device_.createComputePipeline({label, nullptr, &shader_, "main", std::move(constants)});
    layout_ = pipeline_.getBindGroupLayout(0);
  }

  ShaderModule shader_;
  ComputePipeline pipeline_;
  BindGroupLayout layout_;
};

}  // namespace facet::gpu::testing

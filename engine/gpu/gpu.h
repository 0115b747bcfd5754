// facet::gpu — the compute subset of WebGPU, over Vulkan 1.2.
//
// Instance → Adapter → Device → {Queue, Buffer, ShaderModule, BindGroupLayout,
// PipelineLayout, BindGroup, ComputePipeline, CommandEncoder, QuerySet}.
//
// Handles are move-only RAII objects. Internally they share ownership the way
// WebGPU objects do: a bind group keeps its buffers alive, and the queue keeps
// everything a submission uses alive until that submission has finished, so
// dropping a handle early is never a use-after-free on the device.
//
// Misuse raises facet::gpu::Error naming the object (by label) and the rule,
// before anything reaches Vulkan; so does using a moved-from (empty) handle.
// No Vulkan type appears in this header.
//
// Threads: facet::gpu objects are not thread-safe. Use a Device, and every
// object created from it, from one thread at a time (one thread per Device);
// nothing here locks, as recording and submission state is shared unguarded.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace facet::gpu {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {
struct InstanceState;
struct DeviceState;
struct BufferState;
struct ShaderModuleState;
struct BindGroupLayoutState;
struct PipelineLayoutState;
struct BindGroupState;
struct ComputePipelineState;
struct CommandRecording;
struct QuerySetState;
}  // namespace detail

// Move-only handle over shared internal state.
template <class State>
class Handle {
 public:
  Handle() = default;
  explicit Handle(std::shared_ptr<State> state) : state_(std::move(state)) {}
  Handle(Handle&&) noexcept = default;
  Handle& operator=(Handle&&) noexcept = default;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  explicit operator bool() const { return state_ != nullptr; }
  const std::shared_ptr<State>& state() const { return state_; }

 protected:
  std::shared_ptr<State> state_;
};

// ---------------------------------------------------------------- adapters

// In the order requestAdapter prefers them.
enum class AdapterType { DiscreteGpu, IntegratedGpu, VirtualGpu, Cpu, Other };
const char* toString(AdapterType type);

struct Limits {
  std::uint64_t maxBufferSize = 0;
  std::uint64_t maxStorageBufferBindingSize = 0;
  std::uint64_t maxUniformBufferBindingSize = 0;
  std::uint32_t minStorageBufferOffsetAlignment = 0;
  std::uint32_t minUniformBufferOffsetAlignment = 0;
  std::uint32_t maxBindGroups = 0;
  std::uint32_t maxStorageBuffersPerShaderStage = 0;
  std::array<std::uint32_t, 3> maxComputeWorkgroupsPerDimension{};
  std::array<std::uint32_t, 3> maxComputeWorkgroupSize{};
  std::uint32_t maxComputeInvocationsPerWorkgroup = 0;
  std::uint32_t maxComputeWorkgroupStorageSize = 0;
  std::uint32_t subgroupSize = 0;
  double timestampPeriodNs = 0;  // 0: the queue cannot write timestamps
  bool shaderFloat64 = false;
  std::uint64_t maxTexelBufferElements = 0;  // texels in one texel binding
  std::uint32_t minTexelBufferOffsetAlignment = 0;
};

struct AdapterInfo {
  std::string name;
  std::string driver;
  std::string driverInfo;
  std::string apiVersion;
  AdapterType type = AdapterType::Other;
  std::uint32_t vendorId = 0;
  std::uint32_t deviceId = 0;
  std::uint32_t driverVersion = 0;  // the driver's own encoding
  // Names the driver build whose pipeline-cache data fits this adapter
  // (Vulkan's pipelineCacheUUID): data kept under another is not for it.
  std::array<std::uint8_t, 16> pipelineCacheUuid{};
};

// ---------------------------------------------------------------- resources

enum class BufferUsage : std::uint32_t {
  None = 0,
  MapRead = 1u << 0,
  MapWrite = 1u << 1,
  CopySrc = 1u << 2,
  CopyDst = 1u << 3,
  Uniform = 1u << 6,
  Storage = 1u << 7,
  Indirect = 1u << 8,
  Texel = 1u << 9,          // BindingType::TexelBuffer
  StorageTexel = 1u << 10,  // BindingType::StorageTexelBuffer
};
constexpr BufferUsage operator|(BufferUsage a, BufferUsage b) {
  return BufferUsage(std::uint32_t(a) | std::uint32_t(b));
}
constexpr bool has(BufferUsage set, BufferUsage bit) { return (std::uint32_t(set) & std::uint32_t(bit)) != 0; }
std::string toString(BufferUsage usage);

constexpr std::uint64_t kWholeSize = ~std::uint64_t(0);

struct BufferDescriptor {
  std::string label;
  std::uint64_t size = 0;
  BufferUsage usage = BufferUsage::None;
};

// A MapRead or MapWrite buffer stays mapped for its whole life (WebGPU's
// mapAsync collapsed to "wait on the queue first"); mappedRange() is valid once
// the work that writes it has finished (Queue::waitIdle). Nothing guards the
// other direction either: do not write a MapWrite buffer's mapped range while a
// submitted copy from it is in flight (wait for the queue first), or the copy
// may read a mix of old and new bytes.
class Buffer : public Handle<detail::BufferState> {
 public:
  using Handle::Handle;
  const std::string& label() const;
  std::uint64_t size() const;
  BufferUsage usage() const;
  std::span<std::byte> mappedRange();
  template <class T>
  std::span<T> mapped() {
    auto bytes = mappedRange();
    return {reinterpret_cast<T*>(bytes.data()), bytes.size() / sizeof(T)};
  }
};

struct ShaderModuleDescriptor {
  std::string label;
  std::span<const std::uint32_t> code;  // SPIR-V words
};

class ShaderModule : public Handle<detail::ShaderModuleState> {
 public:
  using Handle::Handle;
};

// Texel buffers are buffers read through the texture path: GLSL `uniform
// usamplerBuffer` with texelFetch (TexelBuffer), `layout(rgba32ui) uniform
// uimageBuffer` with imageLoad/imageStore (StorageTexelBuffer). Where a driver
// turns an SSBO load at a computed index into a loop over lanes (lavapipe), a
// texel fetch is one load; and a texel binding is bounded by
// maxTexelBufferElements, not maxStorageBufferBindingSize (far larger on
// lavapipe). The bind group makes the buffer view.
enum class BindingType { Uniform, Storage, ReadOnlyStorage, TexelBuffer, StorageTexelBuffer };
const char* toString(BindingType type);

// Four 32-bit components: 16 bytes per texel. GLSL vec4, uvec4 and ivec4.
enum class TexelFormat { Rgba32Float, Rgba32Uint, Rgba32Sint };
const char* toString(TexelFormat format);

struct BindGroupLayoutEntry {
  std::uint32_t binding = 0;
  BindingType type = BindingType::Storage;
  std::uint64_t minBindingSize = 0;                    // 0: any size
  TexelFormat texelFormat = TexelFormat::Rgba32Float;  // texel bindings only
};

struct BindGroupLayoutDescriptor {
  std::string label;
  std::vector<BindGroupLayoutEntry> entries;
};

class BindGroupLayout : public Handle<detail::BindGroupLayoutState> {
 public:
  using Handle::Handle;
  // Sorted by binding; for a derived layout, what the shader declares.
  const std::vector<BindGroupLayoutEntry>& entries() const;
};

struct PipelineLayoutDescriptor {
  std::string label;
  std::vector<const BindGroupLayout*> bindGroupLayouts;
};

class PipelineLayout : public Handle<detail::PipelineLayoutState> {
 public:
  using Handle::Handle;
};

struct BindGroupEntry {
  std::uint32_t binding = 0;
  const Buffer* buffer = nullptr;
  std::uint64_t offset = 0;
  std::uint64_t size = kWholeSize;
};

struct BindGroupDescriptor {
  std::string label;
  const BindGroupLayout* layout = nullptr;
  std::vector<BindGroupEntry> entries;
};

class BindGroup : public Handle<detail::BindGroupState> {
 public:
  using Handle::Handle;
};

// Pipeline-overridable constants (Vulkan specialization constants), named as
// in the shader source, or by their constant_id written as a decimal string.
struct ConstantEntry {
  std::string key;
  double value = 0;
};

struct ComputePipelineDescriptor {
  std::string label;
  const PipelineLayout* layout = nullptr;  // nullptr: derived from the shader ("auto")
  const ShaderModule* module = nullptr;
  std::string entryPoint = "main";
  std::vector<ConstantEntry> constants;
};

class ComputePipeline : public Handle<detail::ComputePipelineState> {
 public:
  using Handle::Handle;
  // The layout of bind group `index`, as given or as derived from the shader.
  BindGroupLayout getBindGroupLayout(std::uint32_t index) const;
  std::array<std::uint32_t, 3> workgroupSize() const;
};

struct QuerySetDescriptor {
  std::string label;
  std::uint32_t count = 0;
};

// Timestamp queries. Results are read on the host after the queue is idle.
class QuerySet : public Handle<detail::QuerySetState> {
 public:
  using Handle::Handle;
  std::uint32_t count() const;
  std::vector<double> readTimestampsNs(std::uint32_t first, std::uint32_t count) const;
};

// ---------------------------------------------------------------- commands

struct ComputePassTimestampWrites {
  const QuerySet* querySet = nullptr;
  std::uint32_t beginningOfPassWriteIndex = 0;
  std::uint32_t endOfPassWriteIndex = 1;
};

struct ComputePassDescriptor {
  std::string label;
  ComputePassTimestampWrites timestampWrites;
};

class CommandBuffer : public Handle<detail::CommandRecording> {
 public:
  using Handle::Handle;
};

class ComputePassEncoder {
 public:
  ComputePassEncoder(std::shared_ptr<detail::CommandRecording> recording, std::uint64_t passNumber);
  ComputePassEncoder(ComputePassEncoder&&) noexcept;
  ComputePassEncoder& operator=(ComputePassEncoder&&) = delete;
  ComputePassEncoder(const ComputePassEncoder&) = delete;
  ~ComputePassEncoder();  // ends the pass if end() was not called

  void setPipeline(const ComputePipeline& pipeline);
  void setBindGroup(std::uint32_t index, const BindGroup& group);
  void dispatchWorkgroups(std::uint32_t x, std::uint32_t y = 1, std::uint32_t z = 1);
  void dispatchWorkgroupsIndirect(const Buffer& indirect, std::uint64_t offset = 0);
  void end();

 private:
  std::shared_ptr<detail::CommandRecording> recording_;
  std::uint64_t passNumber_;  // which of the encoder's passes this one is
};

struct CommandEncoderDescriptor {
  std::string label;
};

// Records commands; barriers between commands are inserted from the buffers
// each command reads and writes, as WebGPU implementations do.
class CommandEncoder : public Handle<detail::CommandRecording> {
 public:
  using Handle::Handle;
  ComputePassEncoder beginComputePass(const ComputePassDescriptor& descriptor = {});
  void copyBufferToBuffer(const Buffer& source, std::uint64_t sourceOffset, const Buffer& destination,
                          std::uint64_t destinationOffset, std::uint64_t size);
  void clearBuffer(const Buffer& buffer, std::uint64_t offset = 0, std::uint64_t size = kWholeSize);
  CommandBuffer finish();
};

// ---------------------------------------------------------------- device

// Lives inside its Device (Device::queue()); not copyable, so a copy cannot
// outlive or diverge from the device it submits to.
class Queue {
 public:
  explicit Queue(std::shared_ptr<detail::DeviceState> device) : device_(std::move(device)) {}
  Queue(Queue&&) noexcept = default;
  Queue& operator=(Queue&&) noexcept = default;
  Queue(const Queue&) = delete;
  Queue& operator=(const Queue&) = delete;
  void submit(CommandBuffer&& commands);
  void writeBuffer(const Buffer& buffer, std::uint64_t offset, const void* data, std::size_t size);
  template <class T>
  void writeBuffer(const Buffer& buffer, std::uint64_t offset, std::span<const T> data) {
    writeBuffer(buffer, offset, data.data(), data.size_bytes());
  }
  // Blocks until all submitted work (and pending writes) has finished.
  void waitIdle();

 private:
  std::shared_ptr<detail::DeviceState> device_;
};

struct DeviceDescriptor {
  std::string label;
  // What Device::pipelineCacheData() returned for this adapter before,
  // to start the device's pipeline cache from; empty: an empty cache. The
  // driver checks the data's header against itself, and ignores data made by
  // another, but trusts the rest: hand it only bytes known to be intact.
  std::vector<std::byte> pipelineCache;
};

class Device : public Handle<detail::DeviceState> {
 public:
  Device() = default;
  explicit Device(std::shared_ptr<detail::DeviceState> state);
  Device(Device&&) noexcept = default;
  Device& operator=(Device&& other) noexcept;
  ~Device();

  const AdapterInfo& adapterInfo() const;
  const Limits& limits() const;
  Queue& queue();

  Buffer createBuffer(const BufferDescriptor& descriptor);
  ShaderModule createShaderModule(const ShaderModuleDescriptor& descriptor);
  BindGroupLayout createBindGroupLayout(const BindGroupLayoutDescriptor& descriptor);
  PipelineLayout createPipelineLayout(const PipelineLayoutDescriptor& descriptor);
  BindGroup createBindGroup(const BindGroupDescriptor& descriptor);
  // Every pipeline goes through the device's pipeline cache (Vulkan's
  // VkPipelineCache): one the cache holds is not compiled again.
  ComputePipeline createComputePipeline(const ComputePipelineDescriptor& descriptor);
  // The same, for each descriptor, on up to `threads` threads (Vulkan lets
  // pipelines be created concurrently; a driver compiles each on the calling
  // thread). A failure is the first failing descriptor's Error, after every
  // thread has finished.
  std::vector<ComputePipeline> createComputePipelines(std::span<const ComputePipelineDescriptor> descriptors,
                                                      unsigned threads);
  // The pipeline cache's data now (header and all), to keep for the next
  // device on this adapter (DeviceDescriptor::pipelineCache).
  std::vector<std::byte> pipelineCacheData() const;
  CommandEncoder createCommandEncoder(const CommandEncoderDescriptor& descriptor = {});
  QuerySet createQuerySet(const QuerySetDescriptor& descriptor);

 private:
  Queue queue_{nullptr};
};

// ---------------------------------------------------------------- instance

class Adapter {
 public:
  Adapter(std::shared_ptr<detail::InstanceState> instance, std::size_t index);
  const AdapterInfo& info() const;
  const Limits& limits() const;
  Device requestDevice(const DeviceDescriptor& descriptor = {}) const;

 private:
  std::shared_ptr<detail::InstanceState> instance_;
  std::size_t index_;
};

enum class Validation {
  Off,
  IfInstalled,  // Khronos validation layer when present
  Required,     // Error when the layer is not installed
};

// What the caller chose; facet::gpu reads no environment variable of its own.
struct InstanceDescriptor {
  Validation validation = Validation::Off;
};

struct AdapterOptions {
  // Case-insensitive substring of the adapter name. Empty: the first hardware
  // GPU, else the first CPU device.
  std::string name;
};

class Instance : public Handle<detail::InstanceState> {
 public:
  using Handle::Handle;
  static Instance create(const InstanceDescriptor& descriptor = {});

  std::vector<AdapterInfo> enumerateAdapters() const;
  Adapter requestAdapter(const AdapterOptions& options = {}) const;

  bool validationEnabled() const;
  // Validation-layer messages (warnings and errors) since the last call.
  std::vector<std::string> takeValidationMessages() const;
};

}  // namespace facet::gpu

// Internal: the Vulkan objects behind facet::gpu handles. Only engine/gpu/*.cpp
// include this file.
#pragma once

#include <vulkan/vulkan.h>

#include <map>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

#include "engine/gpu/describe.h"
#include "engine/gpu/gpu.h"
#include "engine/gpu/spirv_reflect.h"

namespace facet::gpu::detail {

// The state behind `handle`, or Error("<what> is moved-from or empty"): every
// public entry point goes through this before touching a handle's state.
template <class HandleType>
auto& require(const HandleType& handle, const std::string& what) {
  if (!handle) throw Error(what + " is moved-from or empty");
  return *handle.state();
}

// A facet::gpu enumerator with its Vulkan value and its name. A table of these
// holds one row per enumerator in declaration order, so that row i is
// enumerator i (indexedByKey).
template <class Key, class Vulkan>
struct EnumRow {
  Key key;
  Vulkan vulkan;
  const char* name;
};

template <class Row, std::size_t N>
constexpr bool indexedByKey(const Row (&table)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (std::size_t(table[i].key) != i) return false;
  return true;
}

// Throws Error("<what>: <VkResult name>") when a Vulkan call fails.
void check(VkResult result, const char* what);
const char* resultName(VkResult result);

struct InstanceState {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  std::vector<VkPhysicalDevice> physicalDevices;
  std::vector<AdapterInfo> infos;
  std::vector<Limits> limits;

  std::mutex messagesMutex;
  std::vector<std::string> validationMessages;

  ~InstanceState();
};

struct InFlight {
  std::uint64_t timelineValue = 0;
  VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
  std::vector<std::shared_ptr<void>> resources;
};

struct DeviceState {
  std::shared_ptr<InstanceState> instance;  // outlives the device
  std::size_t adapterIndex = 0;
  std::string label;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  VkPhysicalDeviceMemoryProperties memory{};
  VkCommandPool commandPool = VK_NULL_HANDLE;
  VkPipelineCache pipelineCache = VK_NULL_HANDLE;  // internally synchronized

  VkSemaphore timeline = VK_NULL_HANDLE;
  std::uint64_t lastSubmitted = 0;
  std::vector<InFlight> inFlight;

  // Queue::writeBuffer records into this until the next submit or wait.
  VkCommandBuffer pendingUploads = VK_NULL_HANDLE;
  std::vector<std::shared_ptr<void>> pendingUploadResources;

  const AdapterInfo& info() const { return instance->infos[adapterIndex]; }
  const Limits& limits() const { return instance->limits[adapterIndex]; }

  VkCommandBuffer beginCommandBuffer();
  std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                               VkMemoryPropertyFlags preferred) const;
  void releaseFinished();
  ~DeviceState();
};

struct BufferState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::uint64_t size = 0;
  BufferUsage usage = BufferUsage::None;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  std::byte* mapped = nullptr;
  ~BufferState();
};

// Ends a command buffer begun by DeviceState::beginCommandBuffer, making its
// writes visible to the host.
void endCommandBuffer(VkCommandBuffer cmd);

// Creates a buffer with memory bound; `usage` decides the memory type.
std::shared_ptr<BufferState> createBufferState(const std::shared_ptr<DeviceState>& device, std::string label,
                                               std::uint64_t size, BufferUsage usage);

struct ShaderModuleState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::vector<std::uint32_t> code;  // the driver gets it per pipeline, specialized
  spirv::Reflection reflection;
};

struct BindGroupLayoutState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::vector<BindGroupLayoutEntry> entries;  // sorted by binding
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  const BindGroupLayoutEntry* find(std::uint32_t binding) const;
  // The same object, or entries that agree binding by binding: a bind group
  // made for one can be used where the other is expected.
  bool matches(const BindGroupLayoutState& other) const;
  ~BindGroupLayoutState();
};

struct PipelineLayoutState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::vector<std::shared_ptr<BindGroupLayoutState>> groups;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  ~PipelineLayoutState();
};

struct BoundBuffer {
  std::uint32_t binding = 0;
  std::shared_ptr<BufferState> buffer;
  std::uint64_t size = 0;              // the bound range
  bool written = false;                // the layout lets the shader write it (storage, storage texel)
  VkBufferView view = VK_NULL_HANDLE;  // texel bindings: owned by the bind group
};

struct BindGroupState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::shared_ptr<BindGroupLayoutState> layout;
  std::vector<BoundBuffer> buffers;
  VkDescriptorPool pool = VK_NULL_HANDLE;  // one set per pool: sized exactly
  VkDescriptorSet set = VK_NULL_HANDLE;
  ~BindGroupState();
};

struct ComputePipelineState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::shared_ptr<PipelineLayoutState> layout;
  std::vector<spirv::Binding> shaderBindings;  // checked against bound ranges at dispatch
  std::array<std::uint32_t, 3> workgroupSize{1, 1, 1};
  VkPipeline pipeline = VK_NULL_HANDLE;
  ~ComputePipelineState();
};

struct QuerySetState {
  std::shared_ptr<DeviceState> device;
  std::string label;
  std::uint32_t count = 0;
  std::vector<bool> submitted;  // written by submitted work: safe to wait for
  VkQueryPool pool = VK_NULL_HANDLE;
  ~QuerySetState();
};

// One command buffer being recorded, and after finish(), waiting for submit.
struct CommandRecording {
  std::shared_ptr<DeviceState> device;
  std::string label;
  VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
  std::vector<std::shared_ptr<void>> resources;
  std::vector<std::pair<std::shared_ptr<QuerySetState>, std::uint32_t>> timestampWrites;
  bool finished = false;

  // Hazard tracking since the last barrier.
  std::unordered_set<const BufferState*> writtenSinceBarrier;
  std::unordered_set<const BufferState*> readSinceBarrier;

  // Open compute pass, if any. Passes are numbered so that a pass encoder
  // kept after its end() cannot act on a later pass.
  bool passOpen = false;
  std::uint64_t passNumber = 0;
  std::string passLabel;
  std::shared_ptr<ComputePipelineState> pipeline;
  std::vector<std::shared_ptr<BindGroupState>> bindGroups;
  // The pipeline layout each bind group was bound with: after setPipeline
  // switches layouts, dispatch binds the groups again with the current one.
  std::vector<VkPipelineLayout> bindGroupPipelineLayouts;
  std::shared_ptr<QuerySetState> passTimestamps;
  std::uint32_t passEndTimestampIndex = 0;

  // Inserts a barrier when `reads`/`writes` touch what earlier commands wrote
  // (or `writes` touch what they read), then records them as touched.
  void orderAccess(const std::vector<const BufferState*>& reads, const std::vector<const BufferState*>& writes);
  void requireRecording(const char* operation) const;
  ~CommandRecording();
};

}  // namespace facet::gpu::detail

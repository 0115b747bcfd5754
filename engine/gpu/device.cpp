// Device, queue and buffers.
#include <cstdio>
#include <cstring>

#include "engine/gpu/vk_state.h"

namespace facet::gpu {
namespace detail {
namespace {

// Everything before → everything after, including host reads of mapped memory.
// Used at command-buffer boundaries, where earlier submissions' writes must
// become visible; barriers inside a command buffer are finer (CommandRecording).
void fullBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
}

void barrierToHost(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr,
                       0, nullptr);
}

constexpr BufferUsage kKnownUsages = BufferUsage::MapRead | BufferUsage::MapWrite | BufferUsage::CopySrc |
                                     BufferUsage::CopyDst | BufferUsage::Uniform | BufferUsage::Storage |
                                     BufferUsage::Indirect | BufferUsage::Texel | BufferUsage::StorageTexel;

std::string hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%x", value);
  return text;
}

VkBufferUsageFlags vulkanUsage(BufferUsage usage) {
  VkBufferUsageFlags flags = 0;
  if (has(usage, BufferUsage::CopySrc)) flags |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  if (has(usage, BufferUsage::CopyDst)) flags |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (has(usage, BufferUsage::Uniform)) flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  if (has(usage, BufferUsage::Storage)) flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  if (has(usage, BufferUsage::Indirect)) flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
  if (has(usage, BufferUsage::Texel)) flags |= VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
  if (has(usage, BufferUsage::StorageTexel)) flags |= VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT;
  return flags;
}

void checkBufferDescriptor(const BufferDescriptor& d, const Limits& limits) {
  auto fail = [&](const std::string& rule) { throw Error(describe("buffer", d.label) + ": " + rule); };
  if (d.size == 0) fail("size must be greater than 0");
  if (d.usage == BufferUsage::None) fail("usage must name at least one usage");
  const std::uint32_t unknown = std::uint32_t(d.usage) & ~std::uint32_t(kKnownUsages);
  if (unknown != 0) fail("usage has unknown bits " + hex(unknown));
  if (d.size > limits.maxBufferSize)
    fail("size " + std::to_string(d.size) + " exceeds the device's maxBufferSize " +
         std::to_string(limits.maxBufferSize));
  // WebGPU allows MapRead or MapWrite alone, but with no copy usage such a
  // buffer could never receive or hand on data here: requiring the partner
  // turns a useless buffer into an Error at the point of the mistake.
  const auto allowedWith = [&](BufferUsage mapping, BufferUsage partner) {
    if (!has(d.usage, mapping)) return;
    std::uint32_t others = std::uint32_t(d.usage) & ~std::uint32_t(mapping | partner);
    if (others != 0)
      fail("usage " + toString(d.usage) + ": " + toString(mapping) + " may only be combined with " + toString(partner));
    if (!has(d.usage, partner))
      fail("usage " + toString(d.usage) + ": " + toString(mapping) + " needs " + toString(partner) +
           ", as nothing else can move data into or out of a mapped buffer");
  };
  allowedWith(BufferUsage::MapRead, BufferUsage::CopyDst);
  allowedWith(BufferUsage::MapWrite, BufferUsage::CopySrc);
}

}  // namespace

VkCommandBuffer DeviceState::beginCommandBuffer() {
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = commandPool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer cmd;
  check(vkAllocateCommandBuffers(device, &allocate, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  fullBarrier(cmd);
  return cmd;
}

void endCommandBuffer(VkCommandBuffer cmd) {
  barrierToHost(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

std::uint32_t DeviceState::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                                          VkMemoryPropertyFlags preferred) const {
  std::uint32_t fallback = UINT32_MAX;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
    if (!(typeBits & (1u << i)) || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback == UINT32_MAX) fallback = i;
  }
  if (fallback == UINT32_MAX) throw Error(describe("device", label) + ": no memory type fits the buffer");
  return fallback;
}

void DeviceState::releaseFinished() {
  std::uint64_t completed = 0;
  check(vkGetSemaphoreCounterValue(device, timeline, &completed), "vkGetSemaphoreCounterValue");
  std::erase_if(inFlight, [&](InFlight& work) {
    if (work.timelineValue > completed) return false;
    vkFreeCommandBuffers(device, commandPool, 1, &work.commandBuffer);
    return true;
  });
}

DeviceState::~DeviceState() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  for (auto& work : inFlight) vkFreeCommandBuffers(device, commandPool, 1, &work.commandBuffer);
  if (pendingUploads) vkFreeCommandBuffers(device, commandPool, 1, &pendingUploads);
  vkDestroyPipelineCache(device, pipelineCache, nullptr);
  vkDestroySemaphore(device, timeline, nullptr);
  vkDestroyCommandPool(device, commandPool, nullptr);
  vkDestroyDevice(device, nullptr);
}

BufferState::~BufferState() {
  if (memory) vkFreeMemory(device->device, memory, nullptr);
  if (buffer) vkDestroyBuffer(device->device, buffer, nullptr);
}

std::shared_ptr<BufferState> createBufferState(const std::shared_ptr<DeviceState>& device, std::string label,
                                               std::uint64_t size, BufferUsage usage) {
  auto state = std::make_shared<BufferState>();
  state->device = device;
  state->label = std::move(label);
  state->size = size;
  state->usage = usage;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = vulkanUsage(usage);
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device->device, &info, nullptr, &state->buffer), "vkCreateBuffer");

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device->device, state->buffer, &requirements);
  bool mappable = has(usage, BufferUsage::MapRead) || has(usage, BufferUsage::MapWrite);
  VkMemoryPropertyFlags required =
      mappable ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0;
  VkMemoryPropertyFlags preferred = has(usage, BufferUsage::MapRead) ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT
                                    : mappable                       ? 0
                                                                     : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = requirements.size;
  allocate.memoryTypeIndex = device->findMemoryType(requirements.memoryTypeBits, required, preferred);
  VkResult result = vkAllocateMemory(device->device, &allocate, nullptr, &state->memory);
  if (result != VK_SUCCESS)
    throw Error(describe("buffer", state->label) + ": allocating " + std::to_string(size) +
                " bytes failed: " + resultName(result));
  check(vkBindBufferMemory(device->device, state->buffer, state->memory, 0), "vkBindBufferMemory");
  if (mappable) {
    void* mapped = nullptr;
    check(vkMapMemory(device->device, state->memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    state->mapped = static_cast<std::byte*>(mapped);
  }
  return state;
}

}  // namespace detail

std::string toString(BufferUsage usage) {
  static constexpr std::pair<BufferUsage, const char*> kNames[] = {
      {BufferUsage::MapRead, "MapRead"},          {BufferUsage::MapWrite, "MapWrite"},
      {BufferUsage::CopySrc, "CopySrc"},          {BufferUsage::CopyDst, "CopyDst"},
      {BufferUsage::Uniform, "Uniform"},          {BufferUsage::Storage, "Storage"},
      {BufferUsage::Indirect, "Indirect"},        {BufferUsage::Texel, "Texel"},
      {BufferUsage::StorageTexel, "StorageTexel"}};
  std::string names;
  for (auto [bit, name] : kNames) {
    if (!has(usage, bit)) continue;
    if (!names.empty()) names += '|';
    names += name;
  }
  return names.empty() ? "None" : names;
}

// ---------------------------------------------------------------- Buffer

const std::string& Buffer::label() const { return detail::require(*this, "buffer").label; }
std::uint64_t Buffer::size() const { return detail::require(*this, "buffer").size; }
BufferUsage Buffer::usage() const { return detail::require(*this, "buffer").usage; }

std::span<std::byte> Buffer::mappedRange() {
  detail::require(*this, "buffer");
  if (!state_->mapped)
    throw Error(detail::describe("buffer", state_->label) + ": mappedRange needs usage MapRead or MapWrite, not " +
                toString(state_->usage));
  return {state_->mapped, std::size_t(state_->size)};
}

// ---------------------------------------------------------------- Device

Device::Device(std::shared_ptr<detail::DeviceState> state) : Handle(std::move(state)), queue_(state_) {}

Device::~Device() {
  // In-flight work holds the resources it uses, and they hold the device:
  // finishing the work breaks that cycle.
  if (!state_) return;
  try {
    queue_.waitIdle();
  } catch (const Error&) {
    // A lost device has nothing left to wait for.
  }
}

Device& Device::operator=(Device&& other) noexcept {
  if (this != &other) {
    Device old(std::move(*this));
    state_ = std::move(other.state_);
    queue_ = std::move(other.queue_);
  }
  return *this;
}

const AdapterInfo& Device::adapterInfo() const { return detail::require(*this, "device").info(); }
const Limits& Device::limits() const { return detail::require(*this, "device").limits(); }

Queue& Device::queue() {
  detail::require(*this, "device");
  return queue_;
}

Buffer Device::createBuffer(const BufferDescriptor& descriptor) {
  detail::checkBufferDescriptor(descriptor, limits());
  return Buffer(detail::createBufferState(state_, descriptor.label, descriptor.size, descriptor.usage));
}

// ---------------------------------------------------------------- Queue

namespace {

void submitBatch(detail::DeviceState& d, std::vector<detail::InFlight> work) {
  std::vector<VkCommandBuffer> buffers;
  std::uint64_t value = ++d.lastSubmitted;
  for (auto& w : work) {
    buffers.push_back(w.commandBuffer);
    w.timelineValue = value;
  }
  VkTimelineSemaphoreSubmitInfo timeline{VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO};
  timeline.signalSemaphoreValueCount = 1;
  timeline.pSignalSemaphoreValues = &value;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO, &timeline};
  submit.commandBufferCount = std::uint32_t(buffers.size());
  submit.pCommandBuffers = buffers.data();
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &d.timeline;
  detail::check(vkQueueSubmit(d.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  for (auto& w : work) d.inFlight.push_back(std::move(w));
  d.releaseFinished();
}

// Pending writeBuffer copies go first in the next batch.
std::vector<detail::InFlight> takePendingUploads(detail::DeviceState& d) {
  std::vector<detail::InFlight> work;
  if (d.pendingUploads) {
    detail::endCommandBuffer(d.pendingUploads);
    work.push_back({0, std::exchange(d.pendingUploads, VK_NULL_HANDLE), std::exchange(d.pendingUploadResources, {})});
  }
  return work;
}

// Device::queue() checks its device, but a Queue& taken before the Device was
// moved from outlives that check.
detail::DeviceState& requireDevice(const std::shared_ptr<detail::DeviceState>& device) {
  if (!device) throw Error("queue is moved-from or empty: its Device was moved from or never created");
  return *device;
}
}  // namespace

void Queue::submit(CommandBuffer&& commands) {
  requireDevice(device_);
  auto recording = commands.state();
  if (!recording) throw Error("Queue::submit: the command buffer is empty (moved from or already submitted)");
  if (!recording->finished)
    throw Error(detail::describe("command encoder", recording->label) + ": finish() it before submitting");
  auto work = takePendingUploads(*device_);
  work.push_back({0, std::exchange(recording->commandBuffer, VK_NULL_HANDLE), std::move(recording->resources)});
  submitBatch(*device_, std::move(work));
  for (auto& [querySet, index] : recording->timestampWrites) querySet->submitted[index] = true;
  commands = CommandBuffer();
}

void Queue::writeBuffer(const Buffer& buffer, std::uint64_t offset, const void* data, std::size_t size) {
  requireDevice(device_);
  detail::require(buffer, "Queue::writeBuffer's buffer");
  auto fail = [&](const std::string& rule) {
    throw Error("Queue::writeBuffer to " + detail::describe("buffer", buffer.label()) + ": " + rule);
  };
  if (!has(buffer.usage(), BufferUsage::CopyDst)) fail("needs usage CopyDst, has " + toString(buffer.usage()));
  if (offset % 4 != 0 || size % 4 != 0) fail("offset and size must be multiples of 4 bytes");
  if (offset > buffer.size() || size > buffer.size() - offset)
    fail("range of " + std::to_string(size) + " bytes at offset " + std::to_string(offset) + " exceeds the size " +
         std::to_string(buffer.size()));
  if (size == 0) return;

  auto staging = detail::createBufferState(device_, "staging for " + buffer.label(), size,
                                           BufferUsage::MapWrite | BufferUsage::CopySrc);
  std::memcpy(staging->mapped, data, size);
  detail::DeviceState& d = *device_;
  if (!d.pendingUploads) d.pendingUploads = d.beginCommandBuffer();
  // Two writes to one buffer must land in order.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(d.pendingUploads, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier,
                       0, nullptr, 0, nullptr);
  VkBufferCopy region{0, offset, size};
  vkCmdCopyBuffer(d.pendingUploads, staging->buffer, buffer.state()->buffer, 1, &region);
  d.pendingUploadResources.push_back(staging);
  d.pendingUploadResources.push_back(buffer.state());
}

void Queue::waitIdle() {
  detail::DeviceState& d = requireDevice(device_);
  if (auto uploads = takePendingUploads(d); !uploads.empty()) submitBatch(d, std::move(uploads));
  VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  wait.semaphoreCount = 1;
  wait.pSemaphores = &d.timeline;
  wait.pValues = &d.lastSubmitted;
  detail::check(vkWaitSemaphores(d.device, &wait, UINT64_MAX), "vkWaitSemaphores");
  d.releaseFinished();
}

}  // namespace facet::gpu

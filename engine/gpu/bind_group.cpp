// Bind groups: buffers checked against their layout's bindings and the
// device's limits, written into a descriptor set.
#include <algorithm>
#include <map>

#include "engine/gpu/layouts.h"

namespace facet::gpu {

namespace {

// The range `e` binds, checked against its binding's type and minimum size
// and the device's limits; `fail` throws with the rule it breaks.
template <class Fail>
std::uint64_t checkedRange(const BindGroupEntry& e, const BindGroupLayoutEntry& entry, const Limits& limits,
                           const Fail& fail) {
  using namespace detail;
  const Buffer& buffer = *e.buffer;
  const std::string bufferName = describe("buffer", buffer.label());
  const bool texel = isTexel(entry.type);
  BufferUsage needed = entry.type == BindingType::Uniform              ? BufferUsage::Uniform
                       : entry.type == BindingType::TexelBuffer        ? BufferUsage::Texel
                       : entry.type == BindingType::StorageTexelBuffer ? BufferUsage::StorageTexel
                                                                       : BufferUsage::Storage;
  if (!has(buffer.usage(), needed))
    fail(std::string(toString(entry.type)) + " binding needs a buffer with usage " + toString(needed) + ", but " +
         bufferName + " has " + toString(buffer.usage()));
  std::uint32_t alignment = texel                                ? limits.minTexelBufferOffsetAlignment
                            : entry.type == BindingType::Uniform ? limits.minUniformBufferOffsetAlignment
                                                                 : limits.minStorageBufferOffsetAlignment;
  if (e.offset % alignment != 0)
    fail("offset " + std::to_string(e.offset) + " is not a multiple of " + std::to_string(alignment));
  if (e.offset >= buffer.size()) fail("offset " + std::to_string(e.offset) + " is past the end of " + bufferName);
  std::uint64_t size = e.size == kWholeSize ? buffer.size() - e.offset : e.size;
  if (size == 0) fail("size must be greater than 0");
  if (size > buffer.size() - e.offset)
    fail("range of " + std::to_string(size) + " bytes at offset " + std::to_string(e.offset) + " exceeds " +
         bufferName + " of size " + std::to_string(buffer.size()));
  if (size < entry.minBindingSize)
    fail(bufferName + " is too small for the binding: " + std::to_string(size) + " bytes bound, at least " +
         std::to_string(entry.minBindingSize) + " needed");
  if (texel) {
    if (size % spirv::kTexelBytes != 0)
      fail("a texel binding's size must be a multiple of " + std::to_string(spirv::kTexelBytes) + " (one texel)");
    if (size / spirv::kTexelBytes > limits.maxTexelBufferElements)
      fail(std::to_string(size / spirv::kTexelBytes) + " texels of " + bufferName +
           " exceed the device's maxTexelBufferElements " + std::to_string(limits.maxTexelBufferElements) +
           "; bind a smaller range or split the buffer");
  } else {
    std::uint64_t maxRange =
        entry.type == BindingType::Uniform ? limits.maxUniformBufferBindingSize : limits.maxStorageBufferBindingSize;
    if (size > maxRange)
      fail(std::to_string(size) + " bytes of " + bufferName + " exceed the device's max" +
           (entry.type == BindingType::Uniform ? "Uniform" : "Storage") + "BufferBindingSize " +
           std::to_string(maxRange) + "; bind a smaller range or split the buffer");
    if (entry.type != BindingType::Uniform && size % 4 != 0) fail("a storage binding's size must be a multiple of 4");
  }
  return size;
}

// A view of each texel binding's range, which the bind group owns.
void createTexelViews(detail::BindGroupState& state, VkDevice device,
                      const std::vector<const BindGroupLayoutEntry*>& layoutEntries,
                      const std::vector<VkDescriptorBufferInfo>& infos) {
  using namespace detail;
  for (std::size_t i = 0; i < infos.size(); ++i) {
    if (!isTexel(layoutEntries[i]->type)) continue;
    VkBufferViewCreateInfo view{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    view.buffer = infos[i].buffer;
    view.format = vulkanFormat(layoutEntries[i]->texelFormat);
    view.offset = infos[i].offset;
    view.range = infos[i].range;
    check(vkCreateBufferView(device, &view, nullptr, &state.buffers[i].view), "vkCreateBufferView");
  }
}

// A pool sized exactly for the bindings, its one set, and the set's writes.
void writeDescriptorSet(detail::BindGroupState& state, VkDevice device,
                        const std::vector<const BindGroupLayoutEntry*>& layoutEntries,
                        const std::vector<VkDescriptorBufferInfo>& infos) {
  using namespace detail;
  std::map<VkDescriptorType, std::uint32_t> counts;
  for (const auto* entry : layoutEntries) counts[descriptorType(entry->type)]++;
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : counts) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = std::uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &state.pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = state.pool;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &state.layout->layout;
  check(vkAllocateDescriptorSets(device, &allocate, &state.set), "vkAllocateDescriptorSets");
  std::vector<VkWriteDescriptorSet> writes;
  for (std::size_t i = 0; i < infos.size(); ++i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = state.set;
    w.dstBinding = layoutEntries[i]->binding;
    w.descriptorCount = 1;
    w.descriptorType = descriptorType(layoutEntries[i]->type);
    if (isTexel(layoutEntries[i]->type))
      w.pTexelBufferView = &state.buffers[i].view;
    else
      w.pBufferInfo = &infos[i];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device, std::uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace

BindGroup Device::createBindGroup(const BindGroupDescriptor& descriptor) {
  using namespace detail;
  require(*this, "device");
  const std::string name = describe("bind group", descriptor.label);
  if (!descriptor.layout || !*descriptor.layout) throw Error(name + ": layout is null, moved-from or empty");
  auto state = std::make_shared<BindGroupState>();
  state->device = state_;
  state->label = descriptor.label;
  state->layout = descriptor.layout->state();
  const BindGroupLayoutState& layout = *state->layout;
  const Limits& limits = state_->limits();

  std::vector<VkDescriptorBufferInfo> infos;
  std::vector<const BindGroupLayoutEntry*> layoutEntries;
  for (const BindGroupEntry& e : descriptor.entries) {
    auto fail = [&](const std::string& rule) {
      throw Error(name + ", binding " + std::to_string(e.binding) + ": " + rule);
    };
    const BindGroupLayoutEntry* entry = layout.find(e.binding);
    if (!entry) fail("not in " + describe("bind group layout", layout.label) + " (it has " + bindingList(layout) + ")");
    if (std::find(layoutEntries.begin(), layoutEntries.end(), entry) != layoutEntries.end()) fail("bound twice");
    if (!e.buffer || !*e.buffer) fail("buffer is null, moved-from or empty");
    const std::uint64_t size = checkedRange(e, *entry, limits, fail);
    layoutEntries.push_back(entry);
    infos.push_back({e.buffer->state()->buffer, e.offset, size});
    const bool written = entry->type == BindingType::Storage || entry->type == BindingType::StorageTexelBuffer;
    state->buffers.push_back({e.binding, e.buffer->state(), size, written});
  }
  for (const auto& entry : layout.entries) {
    if (std::find(layoutEntries.begin(), layoutEntries.end(), &entry) == layoutEntries.end())
      throw Error(name + ": binding " + std::to_string(entry.binding) + " of " +
                  describe("bind group layout", layout.label) + " has no buffer");
  }

  createTexelViews(*state, state_->device, layoutEntries, infos);
  writeDescriptorSet(*state, state_->device, layoutEntries, infos);
  return BindGroup(std::move(state));
}

namespace detail {

BindGroupState::~BindGroupState() {
  if (pool) vkDestroyDescriptorPool(device->device, pool, nullptr);
  for (const BoundBuffer& b : buffers)
    if (b.view) vkDestroyBufferView(device->device, b.view, nullptr);
}

}  // namespace detail
}  // namespace facet::gpu

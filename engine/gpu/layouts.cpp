// Bind group layouts and pipeline layouts, and the binding types and texel
// formats they hold.
#include <algorithm>

#include "engine/gpu/layouts.h"

namespace facet::gpu {
namespace detail {

BindGroupLayoutState::~BindGroupLayoutState() {
  if (layout) vkDestroyDescriptorSetLayout(device->device, layout, nullptr);
}
PipelineLayoutState::~PipelineLayoutState() {
  if (layout) vkDestroyPipelineLayout(device->device, layout, nullptr);
}

const BindGroupLayoutEntry* BindGroupLayoutState::find(std::uint32_t binding) const {
  auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.binding == binding; });
  return it == entries.end() ? nullptr : &*it;
}

bool BindGroupLayoutState::matches(const BindGroupLayoutState& other) const {
  if (this == &other) return true;
  if (entries.size() != other.entries.size()) return false;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto &a = entries[i], &b = other.entries[i];
    if (a.binding != b.binding || a.type != b.type || a.minBindingSize != b.minBindingSize) return false;
    if (isTexel(a.type) && a.texelFormat != b.texelFormat) return false;
  }
  return true;
}

namespace {

constexpr EnumRow<BindingType, VkDescriptorType> kBindingTypes[] = {
    {BindingType::Uniform, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, "uniform"},
    {BindingType::Storage, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, "storage"},
    {BindingType::ReadOnlyStorage, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, "read-only storage"},
    {BindingType::TexelBuffer, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, "texel buffer"},
    {BindingType::StorageTexelBuffer, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, "storage texel buffer"},
};
static_assert(indexedByKey(kBindingTypes));

constexpr EnumRow<TexelFormat, VkFormat> kTexelFormats[] = {
    {TexelFormat::Rgba32Float, VK_FORMAT_R32G32B32A32_SFLOAT, "rgba32float"},
    {TexelFormat::Rgba32Uint, VK_FORMAT_R32G32B32A32_UINT, "rgba32uint"},
    {TexelFormat::Rgba32Sint, VK_FORMAT_R32G32B32A32_SINT, "rgba32sint"},
};
static_assert(indexedByKey(kTexelFormats));

// Vulkan requires these formats for texel buffers, but a driver that lacks
// one would otherwise fail only inside vkCreateBufferView.
void checkTexelFormat(const DeviceState& device, const std::string& layoutLabel, const BindGroupLayoutEntry& e) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(device.physicalDevice, vulkanFormat(e.texelFormat), &properties);
  const VkFormatFeatureFlags needed = e.type == BindingType::TexelBuffer ? VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT
                                                                         : VK_FORMAT_FEATURE_STORAGE_TEXEL_BUFFER_BIT;
  if ((properties.bufferFeatures & needed) == 0)
    throw Error(describe("bind group layout", layoutLabel) + ", binding " + std::to_string(e.binding) + ": " +
                describe("adapter", device.info().name) + " does not support " + toString(e.texelFormat) + " in a " +
                toString(e.type));
}

}  // namespace

VkDescriptorType descriptorType(BindingType type) { return kBindingTypes[std::size_t(type)].vulkan; }
VkFormat vulkanFormat(TexelFormat format) { return kTexelFormats[std::size_t(format)].vulkan; }

std::string bindingList(const BindGroupLayoutState& layout) {
  std::string list;
  for (const auto& e : layout.entries) list += (list.empty() ? "" : ", ") + std::to_string(e.binding);
  return list.empty() ? "none" : list;
}

std::shared_ptr<BindGroupLayoutState> createBindGroupLayoutState(const std::shared_ptr<DeviceState>& device,
                                                                 const BindGroupLayoutDescriptor& d) {
  auto state = std::make_shared<BindGroupLayoutState>();
  state->device = device;
  state->label = d.label;
  state->entries = d.entries;
  std::sort(state->entries.begin(), state->entries.end(),
            [](const auto& a, const auto& b) { return a.binding < b.binding; });
  for (std::size_t i = 1; i < state->entries.size(); ++i) {
    if (state->entries[i].binding == state->entries[i - 1].binding)
      throw Error(describe("bind group layout", d.label) + ": binding " + std::to_string(state->entries[i].binding) +
                  " appears twice");
  }
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const auto& e : state->entries) {
    if (isTexel(e.type)) checkTexelFormat(*device, d.label, e);
    bindings.push_back({e.binding, descriptorType(e.type), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = std::uint32_t(bindings.size());
  info.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(device->device, &info, nullptr, &state->layout), "vkCreateDescriptorSetLayout");
  return state;
}

std::shared_ptr<PipelineLayoutState> createPipelineLayoutState(
    const std::shared_ptr<DeviceState>& device, std::string label,
    std::vector<std::shared_ptr<BindGroupLayoutState>> groups) {
  if (groups.size() > device->limits().maxBindGroups)
    throw Error(describe("pipeline layout", label) + ": " + std::to_string(groups.size()) +
                " bind groups exceed the device's maxBindGroups " + std::to_string(device->limits().maxBindGroups));
  auto state = std::make_shared<PipelineLayoutState>();
  state->device = device;
  state->label = std::move(label);
  state->groups = std::move(groups);
  std::vector<VkDescriptorSetLayout> sets;
  for (const auto& g : state->groups) sets.push_back(g->layout);
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = std::uint32_t(sets.size());
  info.pSetLayouts = sets.data();
  check(vkCreatePipelineLayout(device->device, &info, nullptr, &state->layout), "vkCreatePipelineLayout");
  return state;
}

}  // namespace detail

const char* toString(BindingType type) { return detail::kBindingTypes[std::size_t(type)].name; }
const char* toString(TexelFormat format) { return detail::kTexelFormats[std::size_t(format)].name; }

BindGroupLayout Device::createBindGroupLayout(const BindGroupLayoutDescriptor& descriptor) {
  detail::require(*this, "device");
  return BindGroupLayout(detail::createBindGroupLayoutState(state_, descriptor));
}

PipelineLayout Device::createPipelineLayout(const PipelineLayoutDescriptor& descriptor) {
  detail::require(*this, "device");
  std::vector<std::shared_ptr<detail::BindGroupLayoutState>> groups;
  for (std::size_t i = 0; i < descriptor.bindGroupLayouts.size(); ++i) {
    const BindGroupLayout* layout = descriptor.bindGroupLayouts[i];
    if (!layout || !*layout)
      throw Error(detail::describe("pipeline layout", descriptor.label) + ": bind group layout " + std::to_string(i) +
                  " is null, moved-from or empty");
    groups.push_back(layout->state());
  }
  return PipelineLayout(detail::createPipelineLayoutState(state_, descriptor.label, std::move(groups)));
}

const std::vector<BindGroupLayoutEntry>& BindGroupLayout::entries() const {
  return detail::require(*this, "bind group layout").entries;
}

}  // namespace facet::gpu

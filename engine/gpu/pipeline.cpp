// Shader modules, layouts, bind groups and compute pipelines.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "engine/gpu/vk_state.h"

namespace facet::gpu {
namespace detail {

ShaderModuleState::~ShaderModuleState() {
  if (module) vkDestroyShaderModule(device->device, module, nullptr);
}
BindGroupLayoutState::~BindGroupLayoutState() {
  if (layout) vkDestroyDescriptorSetLayout(device->device, layout, nullptr);
}
PipelineLayoutState::~PipelineLayoutState() {
  if (layout) vkDestroyPipelineLayout(device->device, layout, nullptr);
}
BindGroupState::~BindGroupState() {
  if (pool) vkDestroyDescriptorPool(device->device, pool, nullptr);
  for (const BoundBuffer& b : buffers)
    if (b.view) vkDestroyBufferView(device->device, b.view, nullptr);
}
ComputePipelineState::~ComputePipelineState() {
  if (pipeline) vkDestroyPipeline(device->device, pipeline, nullptr);
}

const BindGroupLayoutEntry* BindGroupLayoutState::find(std::uint32_t binding) const {
  auto it = std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return e.binding == binding; });
  return it == entries.end() ? nullptr : &*it;
}

namespace {
bool isTexel(BindingType type) { return type == BindingType::TexelBuffer || type == BindingType::StorageTexelBuffer; }
}  // namespace

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

VkDescriptorType descriptorType(BindingType type) { return kBindingTypes[std::size_t(type)].vulkan; }
VkFormat vulkanFormat(TexelFormat format) { return kTexelFormats[std::size_t(format)].vulkan; }

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

// WebGPU's layout: "auto" — one bind group layout per descriptor set the shader uses.
std::shared_ptr<PipelineLayoutState> deriveLayout(const std::shared_ptr<DeviceState>& device, const std::string& label,
                                                  const spirv::Reflection& reflection) {
  std::uint32_t groupCount = 0;
  for (const auto& b : reflection.bindings) groupCount = std::max(groupCount, b.set + 1);
  std::vector<std::shared_ptr<BindGroupLayoutState>> groups;
  for (std::uint32_t set = 0; set < groupCount; ++set) {
    BindGroupLayoutDescriptor d{label + " group " + std::to_string(set), {}};
    for (const auto& b : reflection.bindings)
      if (b.set == set) d.entries.push_back({b.binding, b.type, b.minSize, b.texelFormat});
    groups.push_back(createBindGroupLayoutState(device, d));
  }
  return createPipelineLayoutState(device, label, std::move(groups));
}

bool compatible(BindingType shader, BindingType layout) {
  return shader == layout || (shader == BindingType::ReadOnlyStorage && layout == BindingType::Storage);
}

void checkLayoutAgainstShader(const std::string& pipelineLabel, const PipelineLayoutState& layout,
                              const spirv::Reflection& reflection) {
  for (const auto& b : reflection.bindings) {
    auto fail = [&](const std::string& rule) {
      throw Error(describe("compute pipeline", pipelineLabel) + ": shader binding (group " + std::to_string(b.set) +
                  ", binding " + std::to_string(b.binding) + (b.name.empty() ? "" : ", '" + b.name + "'") + ") " +
                  rule);
    };
    if (b.set >= layout.groups.size())
      fail("has no bind group layout: " + describe("pipeline layout", layout.label) + " has " +
           std::to_string(layout.groups.size()) + " group(s)");
    const BindGroupLayoutState& group = *layout.groups[b.set];
    const BindGroupLayoutEntry* entry = group.find(b.binding);
    if (!entry)
      fail("is missing from " + describe("bind group layout", group.label) + " (it has " + bindingList(group) + ")");
    if (!compatible(b.type, entry->type))
      fail("is " + std::string(toString(b.type)) + " in the shader but " + toString(entry->type) + " in " +
           describe("bind group layout", group.label));
    if (isTexel(b.type) && b.texelFormat != entry->texelFormat)
      fail("is " + std::string(toString(b.texelFormat)) + " in the shader but " + toString(entry->texelFormat) +
           " in " + describe("bind group layout", group.label));
  }
}

// Specialization data: VkBool32 for bools, the constant's own width otherwise.
struct Specialization {
  std::vector<VkSpecializationMapEntry> entries;
  std::vector<std::byte> data;

  void add(const spirv::SpecConstant& c, double value) {
    std::byte bytes[8];
    std::size_t size = 4;
    if (c.kind == spirv::ScalarKind::Bool) {
      std::uint32_t v = value != 0 ? 1u : 0u;
      std::memcpy(bytes, &v, 4);
    } else if (c.kind == spirv::ScalarKind::Float) {
      size = c.width / 8;
      if (size == 8) {
        std::memcpy(bytes, &value, 8);
      } else {
        float v = float(value);
        std::memcpy(bytes, &v, 4);
      }
    } else {
      size = c.width / 8;
      std::int64_t v = std::int64_t(value);
      std::memcpy(bytes, &v, size);  // little-endian: the low bytes
    }
    entries.push_back({c.id, std::uint32_t(data.size()), size});
    data.insert(data.end(), bytes, bytes + size);
  }
};

double checkedConstant(const std::string& pipelineLabel, const spirv::SpecConstant& c, double value) {
  auto fail = [&](const std::string& rule) {
    throw Error(describe("compute pipeline", pipelineLabel) + ": constant '" +
                (c.name.empty() ? std::to_string(c.id) : c.name) + "' = " + std::to_string(value) + ": " + rule);
  };
  if (!std::isfinite(value)) fail("value must be finite");
  if (c.kind == spirv::ScalarKind::Int || c.kind == spirv::ScalarKind::UInt) {
    if (value != std::trunc(value)) fail("an integer constant needs an integral value");
    double lo = c.kind == spirv::ScalarKind::UInt ? 0.0 : -std::ldexp(1.0, int(c.width) - 1);
    double hi = std::ldexp(1.0, int(c.width) - (c.kind == spirv::ScalarKind::UInt ? 0 : 1)) - 1;
    if (value < lo || value > hi) fail("out of range for a " + std::to_string(c.width) + "-bit integer");
  }
  return value;
}

}  // namespace
}  // namespace detail

const char* toString(BindingType type) { return detail::kBindingTypes[std::size_t(type)].name; }
const char* toString(TexelFormat format) { return detail::kTexelFormats[std::size_t(format)].name; }

ShaderModule Device::createShaderModule(const ShaderModuleDescriptor& descriptor) {
  detail::require(*this, "device");
  auto state = std::make_shared<detail::ShaderModuleState>();
  state->device = state_;
  state->label = descriptor.label;
  state->reflection = spirv::reflect(descriptor.code, descriptor.label);
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = descriptor.code.size_bytes();
  info.pCode = descriptor.code.data();
  detail::check(vkCreateShaderModule(state_->device, &info, nullptr, &state->module), "vkCreateShaderModule");
  return ShaderModule(std::move(state));
}

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
    const Buffer& buffer = *e.buffer;
    const std::string bufferName = describe("buffer", buffer.label());
    const bool texel = isTexel(entry->type);
    BufferUsage needed = entry->type == BindingType::Uniform              ? BufferUsage::Uniform
                         : entry->type == BindingType::TexelBuffer        ? BufferUsage::Texel
                         : entry->type == BindingType::StorageTexelBuffer ? BufferUsage::StorageTexel
                                                                          : BufferUsage::Storage;
    if (!has(buffer.usage(), needed))
      fail(std::string(toString(entry->type)) + " binding needs a buffer with usage " + toString(needed) + ", but " +
           bufferName + " has " + toString(buffer.usage()));
    std::uint32_t alignment = texel                                 ? limits.minTexelBufferOffsetAlignment
                              : entry->type == BindingType::Uniform ? limits.minUniformBufferOffsetAlignment
                                                                    : limits.minStorageBufferOffsetAlignment;
    if (e.offset % alignment != 0)
      fail("offset " + std::to_string(e.offset) + " is not a multiple of " + std::to_string(alignment));
    if (e.offset >= buffer.size()) fail("offset " + std::to_string(e.offset) + " is past the end of " + bufferName);
    std::uint64_t size = e.size == kWholeSize ? buffer.size() - e.offset : e.size;
    if (size == 0) fail("size must be greater than 0");
    if (size > buffer.size() - e.offset)
      fail("range of " + std::to_string(size) + " bytes at offset " + std::to_string(e.offset) + " exceeds " +
           bufferName + " of size " + std::to_string(buffer.size()));
    if (size < entry->minBindingSize)
      fail(bufferName + " is too small for the binding: " + std::to_string(size) + " bytes bound, at least " +
           std::to_string(entry->minBindingSize) + " needed");
    if (texel) {
      if (size % spirv::kTexelBytes != 0)
        fail("a texel binding's size must be a multiple of " + std::to_string(spirv::kTexelBytes) + " (one texel)");
      if (size / spirv::kTexelBytes > limits.maxTexelBufferElements)
        fail(std::to_string(size / spirv::kTexelBytes) + " texels of " + bufferName +
             " exceed the device's maxTexelBufferElements " + std::to_string(limits.maxTexelBufferElements) +
             "; bind a smaller range or split the buffer");
    } else {
      std::uint64_t maxRange =
          entry->type == BindingType::Uniform ? limits.maxUniformBufferBindingSize : limits.maxStorageBufferBindingSize;
      if (size > maxRange)
        fail(std::to_string(size) + " bytes of " + bufferName + " exceed the device's max" +
             (entry->type == BindingType::Uniform ? "Uniform" : "Storage") + "BufferBindingSize " +
             std::to_string(maxRange) + "; bind a smaller range or split the buffer");
      if (entry->type != BindingType::Uniform && size % 4 != 0)
        fail("a storage binding's size must be a multiple of 4");
    }
    layoutEntries.push_back(entry);
    infos.push_back({buffer.state()->buffer, e.offset, size});
    const bool written = entry->type == BindingType::Storage || entry->type == BindingType::StorageTexelBuffer;
    state->buffers.push_back({e.binding, buffer.state(), size, written});
  }
  for (const auto& entry : layout.entries) {
    if (std::find(layoutEntries.begin(), layoutEntries.end(), &entry) == layoutEntries.end())
      throw Error(name + ": binding " + std::to_string(entry.binding) + " of " +
                  describe("bind group layout", layout.label) + " has no buffer");
  }

  for (std::size_t i = 0; i < infos.size(); ++i) {
    if (!isTexel(layoutEntries[i]->type)) continue;
    VkBufferViewCreateInfo view{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    view.buffer = infos[i].buffer;
    view.format = vulkanFormat(layoutEntries[i]->texelFormat);
    view.offset = infos[i].offset;
    view.range = infos[i].range;
    check(vkCreateBufferView(state_->device, &view, nullptr, &state->buffers[i].view), "vkCreateBufferView");
  }

  std::map<VkDescriptorType, std::uint32_t> counts;
  for (const auto* entry : layoutEntries) counts[descriptorType(entry->type)]++;
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : counts) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = std::uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  check(vkCreateDescriptorPool(state_->device, &poolInfo, nullptr, &state->pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = state->pool;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &layout.layout;
  check(vkAllocateDescriptorSets(state_->device, &allocate, &state->set), "vkAllocateDescriptorSets");
  std::vector<VkWriteDescriptorSet> writes;
  for (std::size_t i = 0; i < infos.size(); ++i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = state->set;
    w.dstBinding = layoutEntries[i]->binding;
    w.descriptorCount = 1;
    w.descriptorType = descriptorType(layoutEntries[i]->type);
    if (isTexel(layoutEntries[i]->type))
      w.pTexelBufferView = &state->buffers[i].view;
    else
      w.pBufferInfo = &infos[i];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(state_->device, std::uint32_t(writes.size()), writes.data(), 0, nullptr);
  return BindGroup(std::move(state));
}

ComputePipeline Device::createComputePipeline(const ComputePipelineDescriptor& descriptor) {
  using namespace detail;
  require(*this, "device");
  const std::string name = describe("compute pipeline", descriptor.label);
  if (!descriptor.module || !*descriptor.module) throw Error(name + ": shader module is null, moved-from or empty");
  const ShaderModuleState& module = *descriptor.module->state();
  const spirv::Reflection& reflection = module.reflection;
  const auto& entries = reflection.computeEntryPoints;
  if (std::find(entries.begin(), entries.end(), descriptor.entryPoint) == entries.end())
    throw Error(name + ": " + describe("shader module", module.label) + " has no compute entry point '" +
                descriptor.entryPoint + "'");

  if (reflection.usesPushConstants)
    throw Error(name + ": " + describe("shader module", module.label) +
                " declares push constants, which facet::gpu (like WebGPU) does not have; use a uniform buffer");
  auto state = std::make_shared<ComputePipelineState>();
  state->device = state_;
  state->label = descriptor.label;
  state->shaderBindings = reflection.bindings;
  state->workgroupSize = reflection.workgroupSize;

  Specialization specialization;
  std::map<std::uint32_t, double> overridden;
  for (const ConstantEntry& entry : descriptor.constants) {
    const spirv::SpecConstant* constant = reflection.findConstant(entry.key);
    if (!constant) {
      std::string known;
      for (const auto& c : reflection.specConstants) known += (known.empty() ? "" : ", ") + c.name;
      throw Error(name + ": the shader has no overridable constant '" + entry.key +
                  "' (it has: " + (known.empty() ? "none" : known) + ")");
    }
    if (overridden.count(constant->id)) throw Error(name + ": constant '" + entry.key + "' is given twice");
    overridden[constant->id] = checkedConstant(descriptor.label, *constant, entry.value);
    specialization.add(*constant, entry.value);
  }
  for (int i = 0; i < 3; ++i) {
    auto id = reflection.workgroupSizeSpecIds[i];
    if (id >= 0 && overridden.count(std::uint32_t(id)))
      state->workgroupSize[i] = std::uint32_t(overridden[std::uint32_t(id)]);
  }
  const Limits& limits = state_->limits();
  std::uint64_t invocations = 1;
  for (int i = 0; i < 3; ++i) {
    invocations *= state->workgroupSize[i];
    if (state->workgroupSize[i] == 0 || state->workgroupSize[i] > limits.maxComputeWorkgroupSize[i])
      throw Error(name + ": workgroup size " + std::to_string(state->workgroupSize[i]) + " in dimension " + "xyz"[i] +
                  " is outside [1, " + std::to_string(limits.maxComputeWorkgroupSize[i]) + "]");
  }
  if (invocations > limits.maxComputeInvocationsPerWorkgroup)
    throw Error(name + ": " + std::to_string(invocations) + " invocations per workgroup exceed the device's " +
                "maxComputeInvocationsPerWorkgroup " + std::to_string(limits.maxComputeInvocationsPerWorkgroup));

  if (descriptor.layout) {
    if (!*descriptor.layout) throw Error(name + ": pipeline layout is moved-from or empty");
    state->layout = descriptor.layout->state();
    checkLayoutAgainstShader(descriptor.label, *state->layout, reflection);
  } else {
    state->layout = deriveLayout(state_, descriptor.label, reflection);
  }

  VkSpecializationInfo specializationInfo{};
  specializationInfo.mapEntryCount = std::uint32_t(specialization.entries.size());
  specializationInfo.pMapEntries = specialization.entries.data();
  specializationInfo.dataSize = specialization.data.size();
  specializationInfo.pData = specialization.data.data();
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.module;
  info.stage.pName = descriptor.entryPoint.c_str();
  info.stage.pSpecializationInfo = specialization.entries.empty() ? nullptr : &specializationInfo;
  info.layout = state->layout->layout;
  check(vkCreateComputePipelines(state_->device, VK_NULL_HANDLE, 1, &info, nullptr, &state->pipeline),
        "vkCreateComputePipelines");
  return ComputePipeline(std::move(state));
}

const std::vector<BindGroupLayoutEntry>& BindGroupLayout::entries() const {
  return detail::require(*this, "bind group layout").entries;
}

BindGroupLayout ComputePipeline::getBindGroupLayout(std::uint32_t index) const {
  const auto& groups = detail::require(*this, "compute pipeline").layout->groups;
  if (index >= groups.size())
    throw Error(detail::describe("compute pipeline", state_->label) + ": getBindGroupLayout(" + std::to_string(index) +
                "): the layout has " + std::to_string(groups.size()) + " group(s)");
  return BindGroupLayout(groups[index]);
}

std::array<std::uint32_t, 3> ComputePipeline::workgroupSize() const {
  return detail::require(*this, "compute pipeline").workgroupSize;
}

}  // namespace facet::gpu

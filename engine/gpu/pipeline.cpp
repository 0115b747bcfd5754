// Shader modules and compute pipelines: the shader's entry point, constants,
// workgroup size and bindings checked against the layout, given or derived;
// each pipeline compiled from its module with its constants folded in.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <thread>
#include <unordered_map>

#include "engine/gpu/layouts.h"
#include "engine/gpu/spirv_specialize.h"

namespace facet::gpu {

ShaderModule Device::createShaderModule(const ShaderModuleDescriptor& descriptor) {
  detail::require(*this, "device");
  auto state = std::make_shared<detail::ShaderModuleState>();
  state->device = state_;
  state->label = descriptor.label;
  state->reflection = spirv::reflect(descriptor.code, descriptor.label);
  state->code.assign(descriptor.code.begin(), descriptor.code.end());
  return ShaderModule(std::move(state));
}

namespace detail {

ComputePipelineState::~ComputePipelineState() {
  if (pipeline) vkDestroyPipeline(device->device, pipeline, nullptr);
}

namespace {

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

// A pipeline keeps nothing of the module it was created from, so the
// specialized module lives only while its pipeline is created.
struct TransientShaderModule {
  VkDevice device;
  VkShaderModule module = VK_NULL_HANDLE;
  explicit TransientShaderModule(VkDevice owner) : device(owner) {}
  TransientShaderModule(const TransientShaderModule&) = delete;
  TransientShaderModule& operator=(const TransientShaderModule&) = delete;
  ~TransientShaderModule() {
    if (module) vkDestroyShaderModule(device, module, nullptr);
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

  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> literals;
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
    literals[constant->id] = spirv::literalWords(*constant, entry.value);
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

  const std::shared_ptr<const std::vector<std::uint32_t>> code =
      spirv::specializeOnce(module.code, literals, module.label);
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = code->size() * sizeof(std::uint32_t);
  moduleInfo.pCode = code->data();
  TransientShaderModule specialized{state_->device};
  check(vkCreateShaderModule(state_->device, &moduleInfo, nullptr, &specialized.module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = specialized.module;
  info.stage.pName = descriptor.entryPoint.c_str();
  info.layout = state->layout->layout;
  check(vkCreateComputePipelines(state_->device, state_->pipelineCache, 1, &info, nullptr, &state->pipeline),
        "vkCreateComputePipelines");
  return ComputePipeline(std::move(state));
}

std::vector<ComputePipeline> Device::createComputePipelines(std::span<const ComputePipelineDescriptor> descriptors,
                                                            unsigned threads) {
  detail::require(*this, "device");
  std::vector<ComputePipeline> pipelines(descriptors.size());
  std::vector<std::exception_ptr> errors(descriptors.size());
  std::atomic<std::size_t> next = 0;
  auto work = [&] {
    for (std::size_t i; (i = next++) < descriptors.size();) try {
        pipelines[i] = createComputePipeline(descriptors[i]);
      } catch (...) {
        errors[i] = std::current_exception();
      }
  };
  {
    std::vector<std::jthread> helpers;
    for (std::size_t t = 1; t < std::min<std::size_t>(threads, descriptors.size()); ++t) helpers.emplace_back(work);
    work();
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return pipelines;
}

std::vector<std::byte> Device::pipelineCacheData() const {
  const detail::DeviceState& device = detail::require(*this, "device");
  std::size_t size = 0;
  detail::check(vkGetPipelineCacheData(device.device, device.pipelineCache, &size, nullptr), "vkGetPipelineCacheData");
  std::vector<std::byte> data(size);
  // VK_INCOMPLETE only where the cache grew between the calls, which one thread cannot do.
  detail::check(vkGetPipelineCacheData(device.device, device.pipelineCache, &size, data.data()),
                "vkGetPipelineCacheData");
  data.resize(size);
  return data;
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

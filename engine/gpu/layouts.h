// Internal: creating bind group and pipeline layouts, and what a binding type
// means to Vulkan. layouts.cpp defines these; bind groups and compute
// pipelines (bind_group.cpp, pipeline.cpp) build on them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/gpu/vk_state.h"

namespace facet::gpu::detail {

inline bool isTexel(BindingType type) {
  return type == BindingType::TexelBuffer || type == BindingType::StorageTexelBuffer;
}

VkDescriptorType descriptorType(BindingType type);
VkFormat vulkanFormat(TexelFormat format);

// The layout's binding numbers, for errors: "0, 2, 3" or "none".
std::string bindingList(const BindGroupLayoutState& layout);

std::shared_ptr<BindGroupLayoutState> createBindGroupLayoutState(const std::shared_ptr<DeviceState>& device,
                                                                 const BindGroupLayoutDescriptor& d);
std::shared_ptr<PipelineLayoutState> createPipelineLayoutState(
    const std::shared_ptr<DeviceState>& device, std::string label,
    std::vector<std::shared_ptr<BindGroupLayoutState>> groups);

}  // namespace facet::gpu::detail

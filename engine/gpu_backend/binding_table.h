// Every buffer of a render by its binding number. A number names one buffer
// in every kernel (compute/raycast/common/scene_bindings.glsl,
// compute/raycast/common/trace_bindings.glsl and the kernels' own), so
// each kernel's bind group follows from its layout.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "engine/gpu/gpu.h"
#include "engine/gpu_backend/render_buffers.h"

namespace facet::gpu_backend {

using BindingTable = std::map<std::uint32_t, const gpu::Buffer*>;

BindingTable bindingTable(const GeometryBuffers& g, const ShadingBuffers& s, const TextureBuffers& t,
                          const BandBuffers& b);

// The pipeline's bind group: the table's buffer for each binding its layout has.
gpu::BindGroup bindGroup(gpu::Device& d, const gpu::ComputePipeline& pipeline, const std::string& label,
                         const BindingTable& table);

}  // namespace facet::gpu_backend

// The ray caster's kernels, and a pipeline per variant of specialization
// constants, created at first use and kept, so each variant is compiled once
// per renderer.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"

namespace facet::gpu_backend {

class PipelineCache {
 public:
  explicit PipelineCache(gpu::Device& device);
  gpu::ComputePipeline& get(const char* kernel, const std::vector<gpu::ConstantEntry>& constants);

 private:
  gpu::Device& device_;
  std::map<std::string, gpu::ShaderModule> modules_;
  std::map<std::string, gpu::ComputePipeline> pipelines_;
};

}  // namespace facet::gpu_backend

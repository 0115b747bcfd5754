// The ray caster's kernels, and a pipeline per variant of specialization
// constants, created at first use and kept, so each variant is compiled once
// per renderer and a kernel no render uses is never read by the driver.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"

namespace facet::gpu_backend {

class PipelineCache {
 public:
  explicit PipelineCache(gpu::Device& device);

  // The pipeline of `kernel` with `constants`. Between defer() and
  // createDeferred() a variant not kept yet is only noted: the reference is
  // to an empty pipeline that createDeferred() fills (using it before is a
  // gpu::Error, not a crash).
  gpu::ComputePipeline& get(const char* kernel, const std::vector<gpu::ConstantEntry>& constants);
  void defer();
  // Compiles the variants noted since defer(), together, on every core but
  // one (gpu::Device::createComputePipelines).
  void createDeferred();

  // Wall clock spent creating shader modules and pipelines since the last
  // call, and whether any pipeline was compiled in that time.
  double takeMilliseconds();
  bool takeCompiled();

 private:
  const gpu::ShaderModule& module(const char* kernel);

  gpu::Device& device_;
  std::map<std::string, gpu::ShaderModule> modules_;
  std::map<std::string, gpu::ComputePipeline> pipelines_;
  bool deferring_ = false;
  std::vector<gpu::ComputePipelineDescriptor> deferred_;
  std::vector<std::string> deferredKeys_;
  double milliseconds_ = 0;
  bool compiled_ = false;
};

}  // namespace facet::gpu_backend

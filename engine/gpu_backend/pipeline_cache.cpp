#include "engine/gpu_backend/pipeline_cache.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <span>
#include <thread>
#include <utility>

#include "facet_raycast_kernels/spirv.h"

namespace facet::gpu_backend {

namespace {

class Timer {
 public:
  explicit Timer(double& total) : total_(total) {}
  ~Timer() { total_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count(); }
  Timer(const Timer&) = delete;
  Timer& operator=(const Timer&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::span<const std::uint32_t> kernelCode(const char* kernel) {
  const std::pair<const char*, std::span<const std::uint32_t>> kernels[] = {
      {"dice_grid", raycast::spirv::dice_grid},
      {"dice_cells", raycast::spirv::dice_cells},
      {"build_quadtrees", raycast::spirv::build_quadtrees},
      {"refit_top_levels", raycast::spirv::refit_top_levels},
      {"intersect", raycast::spirv::intersect},
      {"surface", raycast::spirv::surface},
      {"dispatch_args", raycast::spirv::dispatch_args},
      {"fallback", raycast::spirv::fallback},
      {"fallback_resolve", raycast::spirv::fallback_resolve},
      {"shadow", raycast::spirv::shadow},
      {"gather", raycast::spirv::gather},
      {"resolve", raycast::spirv::resolve},
      {"continue_paths", raycast::spirv::continue_paths}};
  for (const auto& [name, code] : kernels)
    if (std::strcmp(name, kernel) == 0) return code;
  throw gpu::Error(std::string("no ray-casting kernel is named '") + kernel + "'");
}

}  // namespace

PipelineCache::PipelineCache(gpu::Device& device) : device_(device) {}

const gpu::ShaderModule& PipelineCache::module(const char* kernel) {
  auto found = modules_.find(kernel);
  if (found != modules_.end()) return found->second;
  return modules_.emplace(kernel, device_.createShaderModule({kernel, kernelCode(kernel)})).first->second;
}

gpu::ComputePipeline& PipelineCache::get(const char* kernel, const std::vector<gpu::ConstantEntry>& constants) {
  std::string key = kernel;
  for (const gpu::ConstantEntry& c : constants) key += " " + c.key + "=" + std::to_string(c.value);
  auto found = pipelines_.find(key);
  if (found != pipelines_.end()) return found->second;
  const Timer timer(milliseconds_);
  gpu::ComputePipelineDescriptor descriptor{key, nullptr, &module(kernel), "main", constants};
  if (deferring_) {
    deferred_.push_back(std::move(descriptor));
    deferredKeys_.push_back(key);
    return pipelines_[key];
  }
  compiled_ = true;
  return pipelines_.emplace(key, device_.createComputePipeline(descriptor)).first->second;
}

void PipelineCache::defer() { deferring_ = true; }

void PipelineCache::createDeferred() {
  deferring_ = false;
  if (deferred_.empty()) return;
  const Timer timer(milliseconds_);
  std::vector<gpu::ComputePipelineDescriptor> descriptors = std::exchange(deferred_, {});
  const std::vector<std::string> keys = std::exchange(deferredKeys_, {});
  try {
    // One core is left to the rest of the machine: on two cores shared with
    // other work, a second compiling thread made the start-up slower
    // (docs/rendering.md, "Start-up").
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency()) - 1;
    std::vector<gpu::ComputePipeline> created = device_.createComputePipelines(descriptors, std::max(1u, threads));
    for (std::size_t i = 0; i < keys.size(); ++i) pipelines_[keys[i]] = std::move(created[i]);
  } catch (...) {
    for (const std::string& key : keys) pipelines_.erase(key);  // no empty pipeline stays kept
    throw;
  }
  compiled_ = true;
}

double PipelineCache::takeMilliseconds() { return std::exchange(milliseconds_, 0.0); }

bool PipelineCache::takeCompiled() { return std::exchange(compiled_, false); }

}  // namespace facet::gpu_backend

#include "engine/gpu_backend/pipeline_cache.h"

#include <cstdint>
#include <span>
#include <utility>

#include "facet_raycast_kernels/spirv.h"

namespace facet::gpu_backend {

PipelineCache::PipelineCache(gpu::Device& device) : device_(device) {
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
  for (const auto& [name, code] : kernels) modules_.emplace(name, device_.createShaderModule({name, code}));
}

gpu::ComputePipeline& PipelineCache::get(const char* kernel, const std::vector<gpu::ConstantEntry>& constants) {
  std::string key = kernel;
  for (const gpu::ConstantEntry& c : constants) key += " " + c.key + "=" + std::to_string(c.value);
  auto found = pipelines_.find(key);
  if (found != pipelines_.end()) return found->second;
  return pipelines_.emplace(key, device_.createComputePipeline({key, nullptr, &modules_.at(kernel), "main", constants}))
      .first->second;
}

}  // namespace facet::gpu_backend

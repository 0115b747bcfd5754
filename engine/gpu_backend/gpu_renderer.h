// The GPU backend: a scene rendered by the compute kernels of
// compute/raycast/ on a gpu::Device, into the same Image as the CPU
// reference and under the same conventions (docs/rendering.md).
//
// Stages, one compute pass each (GPU timestamps per stage), after the
// environment's preparation (wall clock: sampling tables, or the prefiltered
// maps from compute kernels or the disk cache):
//   dice       tessellated method only: k x k limit points per patch, the
//              midpoints of split transition edges, row boxes
//   raygen     camera rays (the centre ray, plus spp stratified ones if > 1)
//   intersect  closest hit per camera ray through the patch BVHs
//   surface    hit point, limit normal, AOVs, per-light unshadowed radiance
//              and the shadow rays, the environment's share (its shadow
//              rays for the sampled method with occlusion); misses only
//              look up the environment
//   shadow     the intersect kernel again, on the shadow rays
//   gather     per camera ray, the contributions whose shadow rays got through
//   resolve    beauty and coverage per pixel
// Large images are rendered in bands of pixels so that no buffer exceeds
// 64 MiB (lavapipe binds at most 128 MiB).
//
// Precision: the kernels compute in float from the double-precision scene.
// The exact method accepts a root within `tolerance` of the ray:
// max(1e-9 x diagonal, 2^-20 x the largest coordinate of the scene and the
// eye) — 8 float ulps, where the CPU's 1e-9 x diagonal is below float's
// resolution — and does not split pieces below max(4 x tolerance, 1e-6 x
// diagonal). Shadow rays leave the surface by max(1e-6 x diagonal (the CPU's
// offset), 32 x tolerance), with the same t_min: a float root's t is only
// known to about tolerance / sin(angle), so the CPU's offset alone lets a
// shadow ray find the surface it leaves.
//
// Specialization constants keep each pipeline to what the scene uses: the
// method, the number of lights, the IBL method and its occlusion, and each
// BRDF model (D, G, F) when all materials share it. Pipelines are created once per variant and kept, so a
// renderer that draws many scenes JITs each variant once.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/image/image.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::gpu_backend {

struct GpuRenderResult {
  Image image;
  std::vector<std::pair<std::string, double>> stageMilliseconds;  // GPU time per stage
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
};

class GpuRenderer {
 public:
  explicit GpuRenderer(gpu::Device& device);

  GpuRenderResult render(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                         const std::function<void(double)>& progress = {});

 private:
  gpu::ComputePipeline& pipeline(const char* kernel, const std::vector<gpu::ConstantEntry>& constants);

  gpu::Device& device_;
  std::map<std::string, gpu::ShaderModule> modules_;
  std::map<std::string, gpu::ComputePipeline> pipelines_;
};

}  // namespace facet::gpu_backend

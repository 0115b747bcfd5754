// The GPU backend: a scene rendered by the compute kernels of
// compute/raycast/ on a gpu::Device, into the same Image as the CPU
// reference and under the same conventions (docs/rendering.md).
//
// Stages (GPU timestamps per compute pass; wall clock for the host's):
//   environment  sampling tables, or the prefiltered maps from compute
//                kernels or the disk cache
//   top levels   the scene packed for the GPU (gpu_scene.h): each object's
//                patch BVH collapsed to 4 wide, patches, all rebased on the eye
//   dice grid    tessellated method only: the micro-grid's limit points
//   dice cells   every cell's box, the last level of each patch's quadtree
//   quadtrees    the quadtrees' upper levels
//   refit        the top levels' boxes shrunk to the diced cells
// then per band of pixels:
//   intersect    closest hit per camera ray (computed in the kernel, as
//                compute/raycast/camera_rays.glsl does wherever it is needed):
//                trace() of compute/raycast/trace.glsl
//   compact      a list's length becomes its pass's indirect dispatch
//   fallbacks    exact method: the cells Newton left undecided, subdivided
//   surface      hit point, limit normal, AOVs, per light slot its unshadowed
//                radiance and, where it needs one, a shadow ray appended to
//                one compacted list; the environment's share; misses only
//                look up the environment
//   shadow rays  any hit along each listed ray (indirect dispatch) clears its slot
//   shadow fallbacks  exact method: the same for the shadow rays' cells
//   gather       per camera ray, the sum of its slots
//   resolve      beauty and coverage per pixel
// Large images are rendered in bands of pixels so that one band's buffers
// stay within 48 MiB (lavapipe binds at most 128 MiB).
//
// Precision: the kernels compute in float, in coordinates relative to the
// eye (rebased in double on the host), so the error follows the scene's
// size as seen from the camera, not its distance from the world origin. The
// exact method accepts a root within rootTolerance() of the ray:
// max(1e-9 x diagonal, 2^-20 x the largest coordinate relative to the eye)
// — 8 float ulps, where the CPU's 1e-9 x diagonal is below float's
// resolution — and does not split pieces below max(4 x tolerance, 1e-6 x
// diagonal). Shadow rays leave the surface by max(1e-6 x diagonal (the CPU's
// offset), 32 x tolerance), with the same t_min: a float root's t is only
// known to about tolerance / sin(angle), so the CPU's offset alone lets a
// shadow ray find the surface it leaves.
//
// The diced geometry (BVH, micro-grid, cell bounds) is kept and reused by
// the next render while its packed scene, method and tolerance hash the same
// (a new eye rebases it, so it is diced again).
//
// Specialization constants keep each pipeline to what the scene uses: the
// method (tracing kernels only), the number of lights, the IBL method and
// its occlusion, and each BRDF model (D, G, F) when all materials share it.
// Pipelines are created once per variant and kept, so a renderer that draws
// many scenes JITs each variant once.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
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
  std::uint64_t cells = 0;            // of the micro-grid
  std::uint64_t newtonFallbacks = 0;  // exact cells whose domain was subdivided
  std::uint64_t gpuBytes = 0;         // scene arrays and one band's ray buffers
};

// The exact method's root tolerance on the GPU (see above).
double rootTolerance(const scene::Scene& scene, const scene::SceneGeometry& geometry);

// The ray caster's kernels, and a pipeline per variant of specialization
// constants, created at first use and kept.
class PipelineCache {
 public:
  explicit PipelineCache(gpu::Device& device);
  gpu::ComputePipeline& get(const char* kernel, const std::vector<gpu::ConstantEntry>& constants);

 private:
  gpu::Device& device_;
  std::map<std::string, gpu::ShaderModule> modules_;
  std::map<std::string, gpu::ComputePipeline> pipelines_;
};

class GpuRenderer {
 public:
  explicit GpuRenderer(gpu::Device& device);

  GpuRenderResult render(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                         const std::function<void(double)>& progress = {});

 private:
  // The last render's diced geometry, reused while the scene's geometry,
  // rates, eye, method and tolerance are the same.
  struct DicedGeometry;
  std::shared_ptr<DicedGeometry> diced_;

  gpu::Device& device_;
  PipelineCache pipelines_;
};

}  // namespace facet::gpu_backend

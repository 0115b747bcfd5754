// The GPU backend: a scene rendered by the compute kernels of
// compute/raycast/ on a gpu::Device, into the same Image as the CPU
// reference and under the same conventions. docs/rendering.md ("The GPU
// path") has the design and the precision rules, docs/architecture.md the
// stages file by file; the stages it reports are those of
// engine/stages/stages.h (GPU timestamps per pass, stage_clock.h; wall clock
// for the host's).
//
// Large images are rendered in bands of pixels, so that one band's buffers
// stay far below the storage binding limit. The diced geometry is kept for
// the next render while its packed scene, method and tolerance hash the
// same, and the textures while they are the same chains. Specialization constants keep each pipeline to what the scene
// uses, and pipelines are kept, so each variant is compiled once per renderer.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/gpu_backend/band_passes.h"
#include "engine/gpu_backend/pipeline_cache.h"
#include "engine/gpu_backend/render_buffers.h"
#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"
#include "engine/stages/stages.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::gpu_backend {

struct GpuRenderResult {
  Image image;
  std::vector<StageTime> stageMilliseconds;  // GPU time per stage
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  std::uint64_t cells = 0;            // of the micro-grid
  std::uint64_t newtonFallbacks = 0;  // exact cells whose domain was subdivided
  std::uint64_t gpuBytes = 0;         // scene arrays and one band's ray buffers
  // Paths (bounces above 0): bounce 0's camera rays to the last bounce's
  // continuation rays.
  std::vector<GpuBounceRays> raysPerBounce;
};

class GpuRenderer {
 public:
  explicit GpuRenderer(gpu::Device& device);

  // With a crop, only its pixels are traced, into an image of the crop's
  // size; each is the same pixel of the whole render.
  GpuRenderResult render(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                         const std::function<void(double)>& progress = {}, const std::optional<PixelRect>& crop = {});

 private:
  // Makes diced_ the geometry of `scene`'s render: kept where the last
  // render's serves it, else packed (checked against the device's limits)
  // and uploaded, unless its packing hashes as the last one's did. Returns
  // whether it must be diced.
  bool keepGeometry(const scene::Scene& scene, const scene::SceneGeometry& geometry, bool tessellated);

  // The last render's diced geometry, reused while the scene's geometry,
  // rates, eye, method and tolerance are the same.
  struct DicedGeometry;
  std::shared_ptr<DicedGeometry> diced_;
  // The last render's textures, reused while the scene's are the same; it
  // holds their texels until a render with other textures or its own end.
  std::optional<TextureBuffers> textures_;

  gpu::Device& device_;
  PipelineCache pipelines_;
};

}  // namespace facet::gpu_backend

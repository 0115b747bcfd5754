// The passes that render one band of pixels (docs/architecture.md, the GPU
// walk): the camera rays traced, shaded, their shadow rays and gather, then,
// with paths (docs/rendering.md, "Paths"), per bounce the continuation and
// its rays through the same passes, and the resolve into the band's beauty.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/gpu_backend/binding_table.h"
#include "engine/gpu_backend/pipeline_cache.h"
#include "engine/gpu_backend/raycast_layout.h"
#include "engine/gpu_backend/render_buffers.h"
#include "engine/gpu_backend/stage_clock.h"
#include "engine/ibl/compensation_tables.h"
#include "engine/ibl/environment_lighting.h"
#include "scenes/scene.h"
#include "scenes/scene_features.h"

namespace facet::gpu_backend {

// The pipelines of one render, by the scene's specialization constants; the
// paths' only with bounces above 0.
struct Kernels {
  gpu::ComputePipeline *intersect, *surface, *dispatchArgs, *shadow, *gather, *resolve;
  gpu::ComputePipeline *cameraFallbacks = nullptr, *resolveCameraFallbacks = nullptr, *shadowFallbacks = nullptr;
  // Paths: the continuation, and the kernels that work off the continuation
  // rays' list (`surface` then writes path states).
  gpu::ComputePipeline *continuePaths = nullptr, *pathIntersect = nullptr, *pathFallbacks = nullptr,
                       *pathGather = nullptr;
};

Kernels kernels(PipelineCache& pipelines, const scene::Scene& scene, const scene::SceneFeatures& features,
                const ibl::EnvironmentLighting* lighting, const ibl::CompensationTables& compensation,
                bool tessellated);

// The rays of one bounce, as engine/cpu/path_tracer.h's BounceRays counts them.
struct GpuBounceRays {
  std::uint64_t rays = 0;  // camera or continuation rays
  std::uint64_t hits = 0;
  std::uint64_t shadowRays = 0;
};

// What a band's passes counted.
struct BandCounts {
  std::uint64_t shadowRays = 0;
  std::uint64_t newtonFallbacks = 0;
  std::uint32_t neededFallbacks = 0;   // the longest fallback list of any bounce
  std::vector<GpuBounceRays> bounces;  // with paths: bounce 0 (camera rays) to the last
};

// Renders the band whose `frame` is written: its `rays` camera rays and, with
// `bounces` above 0, their paths, into the band's beauty and AOVs (copied to
// the host buffers). Stops early where a fallback list overflowed
// (neededFallbacks > frame.fallbackCapacity): the caller renders it again.
BandCounts traceBand(gpu::Device& d, const Kernels& k, const BindingTable& table, BandBuffers& band,
                     gpu_layout::FrameParams frame, int bounces, std::uint64_t rays, std::uint64_t pixels,
                     StageClock& clock);

}  // namespace facet::gpu_backend

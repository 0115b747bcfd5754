// The GPU backend's compute passes and their clock: GPU timestamps per pass,
// reported per stage (engine/stages/stages.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/stages/stages.h"

namespace facet::gpu_backend {

// The compute passes in the order they run, each with its own timestamps.
enum class Pass {
  DiceGrid,
  DiceCells,
  Quadtrees,
  Refit,
  Intersect,
  CompactCameraFallbacks,
  CameraFallbacks,
  ResolveCameraFallbacks,
  Surface,
  CompactShadowRays,
  Shadow,
  CompactShadowFallbacks,
  ShadowFallbacks,
  Gather,
  // Paths: per bounce, the continuation, then its rays as the camera rays'
  // passes from Intersect to Gather work them.
  Continue,
  BounceCompact,
  BounceIntersect,
  BounceCompactFallbacks,
  BounceFallbacks,
  BounceResolveFallbacks,
  BounceSurface,
  BounceCompactShadowRays,
  BounceShadow,
  BounceCompactShadowFallbacks,
  BounceShadowFallbacks,
  BounceGather,
  Resolve,
};
inline constexpr std::size_t kPassCount = std::size_t(Pass::Resolve) + 1;

// Passes of one stage are reported as one, in the order they first ran.
class StageClock {
 public:
  explicit StageClock(gpu::Device& device);

  // A timed pass with its pipeline and bind group set; the caller dispatches.
  gpu::ComputePassEncoder begin(gpu::CommandEncoder& encoder, Pass pass, const gpu::ComputePipeline& pipeline,
                                const gpu::BindGroup& group);

  // A timed pass of one invocation per item.
  void dispatch(gpu::CommandEncoder& encoder, Pass pass, const gpu::ComputePipeline& pipeline,
                const gpu::BindGroup& group, std::uint64_t invocations);

  // After the queue is idle: adds the times of the passes first ... last
  // that ran since the last read, and returns their sum in milliseconds.
  double read(Pass first, Pass last);

  // Appends each stage that ran, or adds to one `stages` already lists.
  void report(std::vector<StageTime>& stages) const;

 private:
  gpu::QuerySet timestamps_;
  double nanoseconds_[kPassCount] = {};
  bool ran_[kPassCount] = {};
  bool unread_[kPassCount] = {};  // ran since the last read
};

}  // namespace facet::gpu_backend

#include "engine/gpu_backend/stage_clock.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

#include "rules/rules.h"

namespace facet::gpu_backend {
namespace {

// The stage each pass is reported as, in the order of Pass: every list's
// compaction is one stage, and the camera rays' fallbacks with their resolve
// another; every pass of a bounce's continuation rays is the stage Bounces.
constexpr Stage kPassStages[] = {
    Stage::DiceGrid,        Stage::DiceCells, Stage::Quadtrees, Stage::Refit,   Stage::Intersect,  Stage::Compact,
    Stage::Fallbacks,       Stage::Fallbacks, Stage::Surface,   Stage::Compact, Stage::ShadowRays, Stage::Compact,
    Stage::ShadowFallbacks, Stage::Gather,    Stage::Continue,  Stage::Bounces, Stage::Bounces,    Stage::Bounces,
    Stage::Bounces,         Stage::Bounces,   Stage::Bounces,   Stage::Bounces, Stage::Bounces,    Stage::Bounces,
    Stage::Bounces,         Stage::Bounces,   Stage::Resolve};
static_assert(std::size(kPassStages) == kPassCount);

std::pair<std::uint32_t, std::uint32_t> workgroups(std::uint64_t invocations) {
  if (invocations > UINT32_MAX) throw gpu::Error("a pass of more than 2^32 invocations");
  const glm::uvec3 grid = rules::f32::workgroup_grid(std::uint32_t(invocations));
  return {grid.x, grid.y};
}

}  // namespace

StageClock::StageClock(gpu::Device& device)
    : timestamps_(device.createQuerySet({"stage timestamps", 2 * std::uint32_t(kPassCount)})) {}

gpu::ComputePassEncoder StageClock::begin(gpu::CommandEncoder& encoder, Pass pass, const gpu::ComputePipeline& pipeline,
                                          const gpu::BindGroup& group) {
  const std::uint32_t index = std::uint32_t(pass);
  ran_[index] = true;
  unread_[index] = true;
  gpu::ComputePassEncoder encoded =
      encoder.beginComputePass({std::string(stageName(kPassStages[index])), {&timestamps_, 2 * index, 2 * index + 1}});
  encoded.setPipeline(pipeline);
  encoded.setBindGroup(0, group);
  return encoded;
}

void StageClock::dispatch(gpu::CommandEncoder& encoder, Pass pass, const gpu::ComputePipeline& pipeline,
                          const gpu::BindGroup& group, std::uint64_t invocations) {
  const auto [x, y] = workgroups(invocations);
  begin(encoder, pass, pipeline, group).dispatchWorkgroups(x, y);
}

double StageClock::read(Pass first, Pass last) {
  double sum = 0;
  for (std::uint32_t p = std::uint32_t(first); p <= std::uint32_t(last); ++p) {
    if (!unread_[p]) continue;
    unread_[p] = false;
    const std::vector<double> ns = timestamps_.readTimestampsNs(2 * p, 2);
    nanoseconds_[p] += ns[1] - ns[0];
    sum += ns[1] - ns[0];
  }
  return sum * 1e-6;
}

void StageClock::report(std::vector<StageTime>& stages) const {
  for (std::size_t p = 0; p < kPassCount; ++p) {
    if (!ran_[p]) continue;
    const Stage stage = kPassStages[p];
    auto same = std::find_if(stages.begin(), stages.end(), [&](const StageTime& t) { return t.stage == stage; });
    if (same == stages.end())
      stages.push_back({stage, nanoseconds_[p] * 1e-6});
    else
      same->milliseconds += nanoseconds_[p] * 1e-6;
  }
}

}  // namespace facet::gpu_backend

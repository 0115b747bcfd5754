// The stages a render reports, with the names `facet render` prints and
// writes as --json keys. Below both backends and the front-end, so the GPU
// backend names its own stages and every reader (analysis, benchmarks, the
// command line) compares these values instead of strings.
#pragma once

#include <string_view>

namespace facet {

// In the order a report lists them; a render reports only the stages it ran.
enum class Stage {
  RefineBvh,    // the front-end: refinement and the patch BVH
  Device,       // start-up: the GPU's instance and device, at a renderer's first GPU render
  Environment,  // the environment's tables or prefiltered maps
  Pipelines,    // start-up: the kernels' pipelines a render is the first to run, and their cache kept
  TraceShade,   // the CPU reference's tracing and shading, as one stage
  // The GPU backend's stages (engine/gpu_backend/stage_clock.h).
  TopLevels,
  DiceGrid,
  DiceCells,
  Quadtrees,
  Refit,
  Intersect,
  Compact,
  Fallbacks,
  Surface,
  ShadowRays,
  ShadowFallbacks,
  Gather,
  // Paths (docs/rendering.md, "Paths"): roulette and continuation, then the
  // continuation rays traced, shaded, their shadow rays and their gather.
  Continue,
  Bounces,
  Resolve,
};

// Distinct per stage: a report's text and --json keys name stages by it.
constexpr std::string_view stageName(Stage stage) {
  switch (stage) {
    case Stage::RefineBvh:
      return "refine + BVH";
    case Stage::Device:
      return "device";
    case Stage::Environment:
      return "environment";
    case Stage::Pipelines:
      return "pipelines";
    case Stage::TraceShade:
      return "trace + shade";
    case Stage::TopLevels:
      return "top levels";
    case Stage::DiceGrid:
      return "dice grid";
    case Stage::DiceCells:
      return "dice cells";
    case Stage::Quadtrees:
      return "quadtrees";
    case Stage::Refit:
      return "refit";
    case Stage::Intersect:
      return "intersect";
    case Stage::Compact:
      return "compact";
    case Stage::Fallbacks:
      return "fallbacks";
    case Stage::Surface:
      return "surface";
    case Stage::ShadowRays:
      return "shadow rays";
    case Stage::ShadowFallbacks:
      return "shadow fallbacks";
    case Stage::Gather:
      return "gather";
    case Stage::Continue:
      return "continue";
    case Stage::Bounces:
      return "bounces";
    case Stage::Resolve:
      return "resolve";
  }
  return "?";
}

// What a renderer pays once (or once per new kernel variant), not per
// image: a kept renderer's later renders do not report it.
constexpr bool isStartup(Stage stage) { return stage == Stage::Device || stage == Stage::Pipelines; }

struct StageTime {
  Stage stage;
  double milliseconds = 0;
};

}  // namespace facet

// Flags that make `facet render` one task of many: which part of the image
// (--crop, --tile), which frames (--frames, --frame, --turntable) or seeds
// (--seeds), how many threads, and how it reports in a farm's logs
// (--quiet, --json).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/pixel_rect.h"
#include "scenes/placement.h"
#include "scenes/scene.h"

namespace facet::cli {

struct FarmOptions {
  std::string crop;    // x0,y0,x1,y1
  std::string tile;    // i/N
  std::string frames;  // A-B or A-B:step
  bool framesGiven = false;
  std::optional<int> frame;
  std::optional<int> turntable;  // frames in a full turn
  std::string seeds;             // A-B: a render per seed
  bool seedsGiven = false;
  std::string turn = "model";    // what it turns: model or environment
  std::optional<unsigned> threads;
  bool quiet = false;
  bool json = false;
};

void addFarmOptions(CLI::App& command, FarmOptions& options);

// The part of the width x height image the flags choose; none: all of it.
// Throws std::invalid_argument naming the flag.
std::optional<PixelRect> chosenCrop(const FarmOptions& options, int width, int height);

// A command renders at most this many frames; a farm splits longer ranges
// across array tasks (docs/reliability.md, "Limits").
constexpr long long kMostFrames = 1000000;

// The frames to render, in order; empty for a still (no frame flag).
std::vector<int> chosenFrames(const FarmOptions& options);

// A command renders at most this many seeds: render --seeds and parity --renders.
constexpr int kMostSeeds = 1024;

// The seeds to render, in order; empty without --seeds.
std::vector<std::uint32_t> chosenSeeds(const FarmOptions& options);

// The camera of `frame`: the keys interpolated, or the still camera where
// there are none.
scene::Camera frameCamera(const scene::Camera& still, const std::vector<scene::CameraKey>& keys, int frame);

// `still` as frame `frame` shows it: its camera keyed, then, for
// --turntable, its model or environment turned (scenes/placement.h).
scene::Scene frameScene(const scene::Scene& still, const FarmOptions& options, int frame);

// --turn model|environment, what a turntable turns: render's and preview's.
CLI::Option* addTurnOption(CLI::App& command, std::string& turn);
scene::TurntableTurn chosenTurn(const std::string& turn);

// `pattern` with its run of '#' replaced by the frame (or the seed, `what`),
// zero-padded to the run's length (Blender's convention); `flag` names it in
// errors.
std::string framePath(const std::string& flag, const std::string& pattern, int frame,
                      const std::string& what = "frame");

// --threads, else the slot's SLURM_CPUS_PER_TASK, else 0 (every core).
unsigned chosenThreads(const FarmOptions& options);

// Lavapipe's worker threads for the GPU backend, unless LP_NUM_THREADS is
// set already; lavapipe reads it when the Vulkan instance is created, so
// this must run before the first GPU render.
void limitLavapipeThreads(unsigned threads);

}  // namespace facet::cli

// One scene of the ceiling benchmark: diced, built into a BVH4, cast by the
// GPU kernels (timed) and checked against brute force on the CPU.
#pragma once

#include <cstddef>
#include <string>

#include "engine/gpu/gpu.h"

namespace facet::benchmarks::ceiling {

constexpr int kSize = 512;

struct Row {
  std::string scene, dicing;
  std::size_t triangles = 0, nodes = 0, nodeBytes = 0, triBytes = 0, hits = 0, shadowRays = 0, occluded = 0;
  int depth = 0;
  double diceMs = 0, buildMs = 0, primaryMs = 0, primaryMrays = 0, shadowMs = 0, shadowMrays = 0;
  std::size_t checked = 0, hitMismatch = 0, shadowChecked = 0, shadowMismatch = 0;
  double maxRelDepth = 0;
};

// `path` is relative to the source tree.
Row measureScene(facet::gpu::Device& device, const std::string& path);

}  // namespace facet::benchmarks::ceiling

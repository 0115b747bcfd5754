// What every contestant of raycast_bench --incoherent is given and returns:
// a list of rays relative to the eye (the GPU's coordinates), and per ray the
// distance to its closest hit (+inf on a miss).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/gpu_backend/raycast_layout.h"

namespace facet::benchmarks::incoherent {

using Ray = facet::gpu_layout::RayRecord;

constexpr float kMiss = std::numeric_limits<float>::infinity();

struct Traced {
  std::vector<float> t;                 // per ray, +inf on a miss
  double ms = 0;                        // one pass over the list
  std::vector<std::uint32_t> triangle;  // the ceiling only: the triangle hit (its leaf order)
};

// Per ray: BVH nodes tested, leaves reached, leaf items finished (facet: a
// leaf is one micro-grid cell; the ceiling's hold up to 16 triangles).
using Work = std::vector<std::array<std::uint32_t, 3>>;

// GPU helpers shared by the GPU contestants.
gpu::Buffer uploadBuffer(gpu::Device& device, const char* label, gpu::BufferUsage usage, const void* data,
                         std::size_t bytes);

// Copies `bytes` of `source` back to the host.
std::vector<std::uint32_t> readBack(gpu::Device& device, const gpu::Buffer& source, std::size_t bytes);

// Submits `encoder`, whose pass writes a uvec4 per ray into `counts`, and
// reads them back as Work.
Work submitAndReadWork(gpu::Device& device, gpu::CommandEncoder& encoder, const gpu::Buffer& counts, std::size_t rays);

}  // namespace facet::benchmarks::incoherent

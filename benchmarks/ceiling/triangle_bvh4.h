// The ceiling's acceleration structure: a binned-SAH binary BVH over the
// triangles, collapsed to facet's 4-wide node layout for the kernels.
#pragma once

#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "benchmarks/ceiling/micro_grid_triangles.h"
#include "engine/gpu_backend/raycast_layout.h"

namespace facet::benchmarks::ceiling {

// facet's node layout (compute/layout/wide_bvh.h), which the kernels test
// with facet's own node code; leaves reference triangle ranges instead of cells.
constexpr std::size_t kNodeTexels = facet::gpu_layout::FACET_BVH4_TEXELS;
constexpr std::uint32_t kEmpty = facet::gpu_layout::FACET_BVH4_EMPTY;

struct Bvh4 {
  std::vector<std::array<std::uint32_t, 4>> nodeTexels;  // kNodeTexels per node
  std::vector<glm::vec4> triTexels;                      // 3 per triangle, in leaf order
  std::vector<Triangle> tris;                            // the same, for the CPU check
  int depth = 0;
  std::size_t nodeCount() const { return nodeTexels.size() / kNodeTexels; }
};

Bvh4 buildBvh4(const std::vector<Triangle>& tris);

}  // namespace facet::benchmarks::ceiling

// The top levels of the scene's 4-wide BVH (compute/layout/wide_bvh.h): each
// object's patch BVH collapsed to four wide, and nodes over the objects.
//
// Their depth is bounded by construction, so the traversal's fixed stack
// (FACET_BVH4_MAX_DEPTH levels) holds every scene the node addressing
// admits: docs/rendering.md, "The depth of the top levels", gives the proof.
// The objects are grouped level by level as their own minimal depth asks
// (a 4-ary tree by Kraft's inequality), and an object's collapse halves its
// patches in leaf order where the SAH tree would not fit what is left.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/gpu_backend/raycast_layout.h"
#include "scenes/patch_bvh.h"

namespace facet::gpu_backend {

struct TopLevelObject {
  const scene::PatchBvh* bvh = nullptr;
  std::vector<scene::Aabb> patchBounds;  // in leaf order
  std::uint32_t quadtreeLevels = 1;      // below each patch
  std::uint32_t nodesPerPatch = 1;       // of each patch's quadtree
};

struct TopLevels {
  std::uint32_t root = 0;
  // The longest path of nodes from the root to a cell, quadtree levels included.
  int depth = 0;
  // Per object, (texel, component) of every reference to a quadtree root:
  // patch slot * nodesPerPatch until the quadtrees are placed.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> patchSlots;
};

// The fewest 4-wide levels over `patches` patches (at least one node).
int wideLevels(std::uint64_t patches);

// Appends the nodes to `texels`, boxes rebased on `origin` and grown by
// `margin`. The objects' fewest levels (wideLevels and their quadtrees')
// must fit the stack together, as they do whenever every node is
// addressable; else it throws std::logic_error.
TopLevels buildTopLevels(const std::vector<TopLevelObject>& objects, const glm::dvec3& origin, double margin,
                         std::vector<Texel>& texels);

}  // namespace facet::gpu_backend

#pragma once
// Bounding volume hierarchy over the limit patches of one surface.
//
// Each patch is bounded by the box of its Bézier control points (plus the
// Gregory alternates): the convex-hull property makes that conservative. The
// tree is built top-down with a binned surface-area heuristic and stored
// depth-first, in double, at most kMaxDepth levels below the root: where the
// SAH would go deeper, a node is halved at its median instead. The CPU
// reference traverses it as it is; the GPU backend collapses it to four wide
// (engine/gpu_backend/top_levels.h).

#include "scenes/bezier_patch.h"

#include <cstddef>
#include <string>
#include <vector>

namespace facet::scene {

class SubdivisionSurface;

struct PatchBvhStatistics {
  int nodes = 0;
  int leaves = 0;
  int maxDepth = 0;
  int patches = 0;
  std::size_t bytes = 0;  // nodes + leaf slots
};

std::string describe(const PatchBvhStatistics& stats);

class PatchBvh {
 public:
  struct Node {
    Aabb bounds;
    int next = 0;        // interior: second child; leaf: first slot in leafPatches()
    int patchCount = 0;  // 0 for interior nodes
    bool leaf() const { return patchCount > 0; }
  };

  // Deep enough for halving subtrees over any int count of patches, so the
  // bound never needs leaves larger than maxLeafPatches.
  static constexpr int kMaxDepth = 48;

  static PatchBvh build(const SubdivisionSurface& surface, int maxLeafPatches = 4);

  const std::vector<Node>& nodes() const { return nodes_; }
  // Leaf slot -> SubdivisionSurface patch index.
  const std::vector<int>& leafPatches() const { return leafPatches_; }

  const PatchBvhStatistics& statistics() const { return statistics_; }

 private:
  std::vector<Node> nodes_;
  std::vector<int> leafPatches_;
  PatchBvhStatistics statistics_;
};

// Box of a patch's control points: encloses the patch.
Aabb patchBounds(const BezierPatch& patch);

}  // namespace facet::scene

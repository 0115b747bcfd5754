#pragma once
// Bounding volume hierarchy over the limit patches of one surface.
//
// Each patch is bounded by the box of its Bézier control points (plus the
// Gregory alternates): the convex-hull property makes that conservative. The
// tree is built top-down with a binned surface-area heuristic and stored
// depth-first, twice: in double for the CPU reference, and as the flat float
// arrays of compute/shared/patch_bvh.h that the GPU uploads as they are.
// Both have the same nodes in the same order.

#include "scenes/bezier_patch.h"
#include "scenes/gpu_layout.h"

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
  std::size_t gpuBytes = 0;  // nodes + patch records + points
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

  static PatchBvh build(const SubdivisionSurface& surface, int maxLeafPatches = 4);

  const std::vector<Node>& nodes() const { return nodes_; }
  // Leaf slot -> SubdivisionSurface patch index (same order as gpuPatches()).
  const std::vector<int>& leafPatches() const { return leafPatches_; }

  const std::vector<gpu_layout::PatchBvhNode>& gpuNodes() const { return gpuNodes_; }
  const std::vector<gpu_layout::PatchRecord>& gpuPatches() const { return gpuPatches_; }
  const std::vector<gpu_layout::PatchPoint>& gpuPoints() const { return gpuPoints_; }

  const PatchBvhStatistics& statistics() const { return statistics_; }

 private:
  std::vector<Node> nodes_;
  std::vector<int> leafPatches_;
  std::vector<gpu_layout::PatchBvhNode> gpuNodes_;
  std::vector<gpu_layout::PatchRecord> gpuPatches_;
  std::vector<gpu_layout::PatchPoint> gpuPoints_;
  PatchBvhStatistics statistics_;
};

// Box of a patch's control points: encloses the patch.
Aabb patchBounds(const BezierPatch& patch);

}  // namespace facet::scene

#include "scenes/patch_bvh.h"

#include "scenes/subdivision_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace facet::scene {

namespace {

constexpr int kBins = 16;

struct BuildItem {
  Aabb bounds;
  glm::dvec3 centroid;
  int patch;
};

class Builder {
 public:
  Builder(std::vector<BuildItem> items, int maxLeafPatches) : items_(std::move(items)), maxLeaf_(maxLeafPatches) {}

  void build(std::vector<PatchBvh::Node>& nodes, std::vector<int>& leafPatches, int& maxDepth) {
    nodes_ = &nodes;
    leafPatches_ = &leafPatches;
    maxDepth_ = &maxDepth;
    if (!items_.empty()) buildNode(0, static_cast<int>(items_.size()), 0);
  }

 private:
  // Levels below a node of `count` patches when every split halves it.
  int balancedLevels(int count) const {
    int levels = 0;
    for (long long capacity = maxLeaf_; capacity < count; capacity *= 2) ++levels;
    return levels;
  }

  // Returns the index of the node it appended (children follow depth-first).
  int buildNode(int begin, int end, int depth) {
    *maxDepth_ = std::max(*maxDepth_, depth);
    Aabb bounds, centroids;
    for (int i = begin; i < end; ++i) {
      bounds.extend(items_[i].bounds);
      centroids.extend(items_[i].centroid);
    }
    const int index = static_cast<int>(nodes_->size());
    nodes_->push_back({bounds, 0, 0});
    const int count = end - begin;

    if (count <= maxLeaf_) {
      (*nodes_)[index].next = static_cast<int>(leafPatches_->size());
      (*nodes_)[index].patchCount = count;
      for (int i = begin; i < end; ++i) leafPatches_->push_back(items_[i].patch);
      return index;
    }
    int mid = splitBySah(begin, end, centroids);
    // The SAH split stands while both sides could still end as halving
    // subtrees within the depth bound; else (and where all centroids
    // coincide) the median halves the node, one level off what is left.
    const int larger = mid < 0 ? count : std::max(mid - begin, end - mid);
    if (mid < 0 || depth + 1 + balancedLevels(larger) > PatchBvh::kMaxDepth) mid = splitAtMedian(begin, end, centroids);
    buildNode(begin, mid, depth + 1);
    const int second = buildNode(mid, end, depth + 1);
    (*nodes_)[index].next = second;
    return index;
  }

  // Partition point of the best binned-SAH split, or -1 if the centroids
  // do not spread along any axis.
  int splitBySah(int begin, int end, const Aabb& centroids) {
    double bestCost = std::numeric_limits<double>::infinity();
    int bestAxis = -1, bestBin = -1;
    for (int axis = 0; axis < 3; ++axis) {
      double extent = centroids.hi[axis] - centroids.lo[axis];
      if (!(extent > 0.0)) continue;
      Aabb binBounds[kBins];
      int binCounts[kBins] = {};
      for (int i = begin; i < end; ++i) {
        int b = binOf(items_[i].centroid[axis], centroids.lo[axis], extent);
        binBounds[b].extend(items_[i].bounds);
        ++binCounts[b];
      }
      double rightArea[kBins];
      int rightCount[kBins];
      Aabb accumulated;
      int accumulatedCount = 0;
      for (int b = kBins - 1; b > 0; --b) {
        accumulated.extend(binBounds[b]);
        accumulatedCount += binCounts[b];
        rightArea[b] = accumulated.surfaceArea();
        rightCount[b] = accumulatedCount;
      }
      accumulated = Aabb();
      accumulatedCount = 0;
      for (int b = 1; b < kBins; ++b) {
        accumulated.extend(binBounds[b - 1]);
        accumulatedCount += binCounts[b - 1];
        if (accumulatedCount == 0 || rightCount[b] == 0) continue;
        double cost = accumulated.surfaceArea() * accumulatedCount + rightArea[b] * rightCount[b];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBin = b;
        }
      }
    }
    if (bestAxis < 0) return -1;
    double extent = centroids.hi[bestAxis] - centroids.lo[bestAxis];
    auto middle = std::partition(items_.begin() + begin, items_.begin() + end, [&](const BuildItem& item) {
      return binOf(item.centroid[bestAxis], centroids.lo[bestAxis], extent) < bestBin;
    });
    return static_cast<int>(middle - items_.begin());
  }

  // The middle of the items by centroid along their widest axis.
  int splitAtMedian(int begin, int end, const Aabb& centroids) {
    const glm::dvec3 extent = centroids.hi - centroids.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const int mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                     [axis](const BuildItem& a, const BuildItem& b) { return a.centroid[axis] < b.centroid[axis]; });
    return mid;
  }

  static int binOf(double value, double lo, double extent) {
    int b = static_cast<int>(kBins * (value - lo) / extent);
    return std::clamp(b, 0, kBins - 1);
  }

  std::vector<BuildItem> items_;
  int maxLeaf_;
  std::vector<PatchBvh::Node>* nodes_ = nullptr;
  std::vector<int>* leafPatches_ = nullptr;
  int* maxDepth_ = nullptr;
};

}  // namespace

Aabb patchBounds(const BezierPatch& patch) {
  Aabb box;
  for (const glm::dvec3& p : patch.points) box.extend(p);
  if (patch.gregory)
    for (const glm::dvec3& p : patch.alternates) box.extend(p);
  return box;
}

PatchBvh PatchBvh::build(const SubdivisionSurface& surface, int maxLeafPatches) {
  std::vector<BuildItem> items;
  items.reserve(surface.patchCount());
  for (int p = 0; p < surface.patchCount(); ++p) {
    Aabb box = patchBounds(surface.bezierPatch(p));
    items.push_back({box, box.centre(), p});
  }

  PatchBvh bvh;
  int maxDepth = 0;
  Builder(std::move(items), std::max(1, maxLeafPatches)).build(bvh.nodes_, bvh.leafPatches_, maxDepth);

  PatchBvhStatistics& stats = bvh.statistics_;
  stats.nodes = static_cast<int>(bvh.nodes_.size());
  stats.leaves =
      static_cast<int>(std::count_if(bvh.nodes_.begin(), bvh.nodes_.end(), [](const Node& n) { return n.leaf(); }));
  stats.maxDepth = maxDepth;
  stats.patches = static_cast<int>(bvh.leafPatches_.size());
  stats.bytes = bvh.nodes_.size() * sizeof(Node) + bvh.leafPatches_.size() * sizeof(int);
  return bvh;
}

std::string describe(const PatchBvhStatistics& stats) {
  std::ostringstream out;
  out << "patch BVH: " << stats.patches << " patches, " << stats.nodes << " nodes (" << stats.leaves
      << " leaves, depth " << stats.maxDepth << "), " << (stats.bytes + 512) / 1024 << " KiB";
  return out.str();
}

}  // namespace facet::scene

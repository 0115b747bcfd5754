#include "benchmarks/ceiling/triangle_bvh4.h"

#include <glm/common.hpp>

#include <algorithm>
#include <bit>
#include <limits>

namespace facet::benchmarks::ceiling {
namespace {

using glm::vec3;

constexpr std::uint32_t kLeaf = 0x80000000u;
constexpr int kMaxLeaf = 4, kBins = 16;

struct Box {
  vec3 lo{kInf}, hi{-kInf};
  void extend(vec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void extend(const Box& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
  float area() const {
    const vec3 e = glm::max(hi - lo, vec3(0.0f));
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

struct BinaryNode {
  Box box;
  int left = -1, right = -1;  // -1: a leaf of triangles [first, first + count) of the order
  int first = 0, count = 0;
};

// Binned SAH over centroids, every axis, a traversal step costing as much as
// one triangle test. Leaves of up to 4 triangles: 8 gave the same trees here.
struct BinaryBuilder {
  std::vector<Box> boxes;
  std::vector<vec3> centroids;
  std::vector<int> order;
  std::vector<BinaryNode> nodes;

  explicit BinaryBuilder(const std::vector<Triangle>& t) : boxes(t.size()), centroids(t.size()), order(t.size()) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      boxes[i].extend(t[i].a), boxes[i].extend(t[i].b), boxes[i].extend(t[i].c);
      centroids[i] = 0.5f * (boxes[i].lo + boxes[i].hi);
      order[i] = int(i);
    }
    nodes.reserve(2 * t.size());
    build(0, int(t.size()));
  }

  int build(int first, int count) {
    const int index = int(nodes.size());
    nodes.push_back({});
    Box box, centres;
    for (int i = first; i < first + count; ++i) box.extend(boxes[order[i]]), centres.extend(centroids[order[i]]);
    nodes[index].box = box;
    float bestCost = std::numeric_limits<float>::max();
    int bestAxis = -1, bestBin = 0;
    for (int axis = 0; axis < 3 && count > 1; ++axis) {
      const float lo = centres.lo[axis], extent = centres.hi[axis] - lo;
      if (!(extent > 0)) continue;
      std::array<Box, kBins> bins;
      std::array<int, kBins> counts{};
      for (int i = first; i < first + count; ++i) {
        const int b = std::min(kBins - 1, int(kBins * (centroids[order[i]][axis] - lo) / extent));
        bins[b].extend(boxes[order[i]]), ++counts[b];
      }
      std::array<float, kBins> rightCost{};
      Box acc;
      for (int b = kBins - 1, n = 0; b > 0; --b) acc.extend(bins[b]), n += counts[b], rightCost[b] = n * acc.area();
      acc = Box{};
      for (int b = 0, n = 0; b < kBins - 1; ++b) {
        acc.extend(bins[b]), n += counts[b];
        const float cost = n * acc.area() + rightCost[b + 1];
        if (n > 0 && n < count && cost < bestCost) bestCost = cost, bestAxis = axis, bestBin = b;
      }
    }
    const float leafCost = float(count) * box.area(), splitCost = box.area() + bestCost;
    if (count == 1 || (count <= kMaxLeaf && leafCost <= splitCost) || (bestAxis < 0 && count <= kMaxLeaf)) {
      nodes[index].first = first, nodes[index].count = count;
      return index;
    }
    int middle = first + count / 2;  // all centroids equal: split the list
    if (bestAxis >= 0) {
      const float lo = centres.lo[bestAxis], extent = centres.hi[bestAxis] - lo;
      middle = int(std::partition(order.begin() + first, order.begin() + first + count,
                                  [&](int t) {
                                    return std::min(kBins - 1, int(kBins * (centroids[t][bestAxis] - lo) / extent)) <=
                                           bestBin;
                                  }) -
                   order.begin());
    }
    const int left = build(first, middle - first);
    const int right = build(middle, first + count - middle);
    nodes[index].left = left, nodes[index].right = right;
    return index;
  }
};

// The binary tree collapsed to 4-wide: a node adopts its children, then
// keeps opening the largest inner one until it has four.
struct Collapser {
  const BinaryBuilder& binary;
  Bvh4& out;

  std::uint32_t reference(int b, int depth) {
    const BinaryNode& n = binary.nodes[b];
    if (n.left < 0) return kLeaf | std::uint32_t(n.count - 1) << 27 | std::uint32_t(n.first);
    return wide({n.left, n.right}, depth);
  }

  std::uint32_t wide(std::vector<int> children, int depth) {
    out.depth = std::max(out.depth, depth);
    while (children.size() < 4) {
      int open = -1;
      for (int c = 0; c < int(children.size()); ++c) {
        const BinaryNode& n = binary.nodes[children[c]];
        if (n.left >= 0 && (open < 0 || n.box.area() > binary.nodes[children[open]].box.area())) open = c;
      }
      if (open < 0) break;
      const BinaryNode& n = binary.nodes[children[open]];
      children[open] = n.left;
      children.push_back(n.right);
    }
    const std::size_t index = out.nodeCount();
    out.nodeTexels.resize(out.nodeTexels.size() + kNodeTexels, {0, 0, 0, 0});
    std::array<std::uint32_t, 4> refs{kEmpty, kEmpty, kEmpty, kEmpty};
    for (std::size_t c = 0; c < children.size(); ++c) {
      const Box& box = binary.nodes[children[c]].box;
      for (int axis = 0; axis < 3; ++axis) {
        out.nodeTexels[index * kNodeTexels + 2 * axis][c] = std::bit_cast<std::uint32_t>(box.lo[axis]);
        out.nodeTexels[index * kNodeTexels + 2 * axis + 1][c] = std::bit_cast<std::uint32_t>(box.hi[axis]);
      }
      refs[c] = reference(children[c], depth + 1);
    }
    out.nodeTexels[index * kNodeTexels + gpu_layout::FACET_BVH4_REFERENCES] = refs;
    return std::uint32_t(index);
  }
};

}  // namespace

Bvh4 buildBvh4(const std::vector<Triangle>& tris) {
  const BinaryBuilder binary(tris);
  Bvh4 out;
  const BinaryNode& root = binary.nodes[0];
  Collapser{binary, out}.wide(root.left < 0 ? std::vector<int>{0} : std::vector<int>{root.left, root.right}, 1);
  for (int t : binary.order) {
    const Triangle& tri = tris[t];
    out.tris.push_back(tri);
    out.triTexels.insert(out.triTexels.end(),
                         {glm::vec4(tri.a, 0), glm::vec4(tri.b - tri.a, 0), glm::vec4(tri.c - tri.a, 0)});
  }
  return out;
}

}  // namespace facet::benchmarks::ceiling

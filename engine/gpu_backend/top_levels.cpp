#include "engine/gpu_backend/top_levels.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

// Float bounds that still contain the double ones.
float roundDown(double value) {
  const float f = float(value);
  return double(f) > value ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double value) {
  const float f = float(value);
  return double(f) < value ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

std::uint32_t bits(float value) { return std::bit_cast<std::uint32_t>(value); }

// Appends an empty node (every slot EMPTY) and returns its index.
std::uint32_t appendNode(std::vector<Texel>& texels) {
  const std::uint32_t index = std::uint32_t(texels.size() / layout::FACET_BVH4_TEXELS);
  texels.resize(texels.size() + layout::FACET_BVH4_TEXELS, Texel{0, 0, 0, 0});
  texels[std::size_t(index) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES] =
      Texel{layout::FACET_BVH4_EMPTY, layout::FACET_BVH4_EMPTY, layout::FACET_BVH4_EMPTY, layout::FACET_BVH4_EMPTY};
  return index;
}

// Child `slot` of `node`: its box, rebased on `origin`, grown by `margin` and
// rounded outwards, and its reference.
void writeChild(std::vector<Texel>& texels, std::uint32_t node, std::size_t slot, const scene::Aabb& bounds,
                std::uint32_t reference, const glm::dvec3& origin, double margin) {
  const std::size_t base = std::size_t(node) * layout::FACET_BVH4_TEXELS;
  for (int axis = 0; axis < 3; ++axis) {
    texels[base + 2 * std::size_t(axis)][slot] = bits(roundDown(bounds.lo[axis] - origin[axis] - margin));
    texels[base + 2 * std::size_t(axis) + 1][slot] = bits(roundUp(bounds.hi[axis] - origin[axis] + margin));
  }
  texels[base + layout::FACET_BVH4_REFERENCES][slot] = reference;
}

// What an object adds below a node at its place: its fewest wide levels and
// its quadtrees' (an object without patches has one empty node).
int minimalDepth(const TopLevelObject& object) {
  const std::size_t patches = object.bvh->leafPatches().size();
  return wideLevels(patches) + (patches > 0 ? int(object.quadtreeLevels) : 0);
}

// A wide node's child while it is being chosen: one patch (its slot in leaf
// order), a node of the binary patch BVH, or a run of patches in leaf order
// (a binary subtree's patches are consecutive there).
struct Candidate {
  enum Kind { Patch, Node, Run } kind = Patch;
  int index = 0;  // Patch, Run: first slot; Node: the binary node
  int count = 1;  // patches below
  scene::Aabb bounds;
};

// Collapses one object's binary patch BVH into 4-wide nodes, at most
// `budget` levels deep. Each node takes the binary subtree's largest boxes
// as children until it has four (the usual collapse, as in Embree's BVH4
// builders) while every child still fits the levels left; where one would
// not, the node's patches are quartered in leaf order instead, which needs
// one level fewer each time.
class Collapse {
 public:
  Collapse(const TopLevelObject& object, int budget, const glm::dvec3& origin, double margin,
           std::vector<Texel>& texels)
      : bvh_(*object.bvh),
        patchBounds_(object.patchBounds),
        budget_(budget),
        nodesPerPatch_(object.nodesPerPatch),
        origin_(origin),
        margin_(margin),
        texels_(texels),
        first_(bvh_.nodes().size()),
        count_(bvh_.nodes().size()) {
    // Children follow their parent in the depth-first order: count backwards.
    for (std::size_t i = bvh_.nodes().size(); i-- > 0;) {
      const scene::PatchBvh::Node& node = bvh_.nodes()[i];
      first_[i] = node.leaf() ? node.next : first_[i + 1];
      count_[i] = node.leaf() ? node.patchCount : count_[i + 1] + count_[std::size_t(node.next)];
    }
  }

  // Returns the root's node index.
  std::uint32_t run() {
    if (bvh_.nodes().empty()) {
      depth_ = 1;
      return appendNode(texels_);
    }
    if (wideLevels(std::uint64_t(count_[0])) > budget_)
      throw std::logic_error("an object's top levels do not fit the GPU traversal's stack");
    return emit(nodeCandidate(0), 1);
  }

  int depth() const { return depth_; }
  const std::vector<std::pair<std::size_t, std::size_t>>& patchSlots() const { return patchSlots_; }

 private:
  Candidate nodeCandidate(int node) const {
    return {Candidate::Node, node, count_[std::size_t(node)], bvh_.nodes()[std::size_t(node)].bounds};
  }
  Candidate runCandidate(int first, int count) const {
    if (count == 1) return {Candidate::Patch, first, 1, patchBounds_[std::size_t(first)]};
    scene::Aabb bounds;
    for (int slot = first; slot < first + count; ++slot) bounds.extend(patchBounds_[std::size_t(slot)]);
    return {Candidate::Run, first, count, bounds};
  }

  std::vector<Candidate> expand(const Candidate& c) const {
    const scene::PatchBvh::Node& node = bvh_.nodes()[std::size_t(c.index)];
    std::vector<Candidate> children;
    if (node.leaf()) {
      for (int slot = node.next; slot < node.next + node.patchCount; ++slot) children.push_back(runCandidate(slot, 1));
    } else {
      children.push_back(nodeCandidate(c.index + 1));
      children.push_back(nodeCandidate(node.next));
    }
    return children;
  }

  // The greedy collapse's children of binary node `c`.
  std::vector<Candidate> greedyChildren(const Candidate& c) const {
    std::vector<Candidate> children = expand(c);
    while (children.size() < 4) {
      int widest = -1;
      for (std::size_t i = 0; i < children.size(); ++i) {
        if (children[i].kind != Candidate::Node) continue;
        const scene::PatchBvh::Node& node = bvh_.nodes()[std::size_t(children[i].index)];
        const std::size_t grows = node.leaf() ? std::size_t(node.patchCount) : 2;
        if (children.size() - 1 + grows > 4) continue;
        if (widest < 0 || children[i].bounds.surfaceArea() > children[std::size_t(widest)].bounds.surfaceArea())
          widest = int(i);
      }
      if (widest < 0) break;
      std::vector<Candidate> grown = expand(children[std::size_t(widest)]);
      children.erase(children.begin() + widest);
      children.insert(children.end(), grown.begin(), grown.end());
    }
    return children;
  }

  // Four runs of the patches first .. first + count - 1, as even as they go.
  std::vector<Candidate> quarter(int first, int count) const {
    std::vector<Candidate> children;
    for (int part = 0; part < 4; ++part) {
      const int size = count / 4 + (part < count % 4 ? 1 : 0);
      if (size > 0) children.push_back(runCandidate(first, size));
      first += size;
    }
    return children;
  }

  // The node for `c` at level `depth`; c's patches fit the levels from
  // `depth` to the budget.
  std::uint32_t emit(const Candidate& c, int depth) {
    depth_ = std::max(depth_, depth);
    std::vector<Candidate> children;
    if (c.kind == Candidate::Node) {
      children = greedyChildren(c);
      const bool fits = std::all_of(children.begin(), children.end(), [&](const Candidate& child) {
        return child.kind == Candidate::Patch || depth + wideLevels(std::uint64_t(child.count)) <= budget_;
      });
      if (!fits) children = quarter(first_[std::size_t(c.index)], c.count);
    } else {
      children = quarter(c.index, c.count);
    }
    const std::uint32_t index = appendNode(texels_);
    for (std::size_t slot = 0; slot < children.size(); ++slot) {
      const Candidate& child = children[slot];
      const bool patch = child.kind == Candidate::Patch;
      const std::uint32_t reference = patch ? std::uint32_t(child.index) * nodesPerPatch_ : emit(child, depth + 1);
      writeChild(texels_, index, slot, child.bounds, reference, origin_, margin_);
      if (patch)
        patchSlots_.push_back({std::size_t(index) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES, slot});
    }
    return index;
  }

  const scene::PatchBvh& bvh_;
  const std::vector<scene::Aabb>& patchBounds_;
  int budget_;
  std::uint32_t nodesPerPatch_;
  glm::dvec3 origin_;
  double margin_;
  std::vector<Texel>& texels_;
  std::vector<int> first_, count_;  // per binary node: its first leaf slot and its patches
  int depth_ = 0;
  std::vector<std::pair<std::size_t, std::size_t>> patchSlots_;
};

// The nodes over the objects, as a tree of groups: groups 0 .. objects - 1
// are the objects themselves.
struct Group {
  scene::Aabb bounds;
  int demand = 0;  // the levels from this group's place down to the deepest cell
  std::vector<int> children;
};

// Level by level from the smallest demand up: the groups whose demand the
// level meets are sorted along the widest axis of their centres and taken
// four at a time into a group one level higher (one left alone moves up as
// it is). Level t then holds ceil(sum 4^demand / 4^t) groups, so the root's
// level is ceil(log4(sum 4^demand)): Kraft's inequality, met with equality.
int groupObjects(std::vector<Group>& groups) {
  std::vector<int> waiting(groups.size());
  for (std::size_t i = 0; i < groups.size(); ++i) waiting[i] = int(i);
  std::vector<int> ready;
  int level = std::numeric_limits<int>::max();
  for (const Group& g : groups) level = std::min(level, g.demand);
  while (true) {
    auto joins = std::stable_partition(waiting.begin(), waiting.end(),
                                       [&](int g) { return groups[std::size_t(g)].demand > level; });
    ready.insert(ready.end(), joins, waiting.end());
    waiting.erase(joins, waiting.end());
    if (ready.size() == 1 && waiting.empty()) return ready.front();
    if (ready.size() > 1) {
      scene::Aabb centres;
      for (int g : ready) centres.extend(groups[std::size_t(g)].bounds.centre());
      const glm::dvec3 extent = centres.hi - centres.lo;
      const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
      std::stable_sort(ready.begin(), ready.end(), [&](int a, int b) {
        return groups[std::size_t(a)].bounds.centre()[axis] < groups[std::size_t(b)].bounds.centre()[axis];
      });
      std::vector<int> next;
      for (std::size_t begin = 0; begin < ready.size(); begin += 4) {
        const std::size_t end = std::min(ready.size(), begin + 4);
        if (end - begin == 1) {
          next.push_back(ready[begin]);
          continue;
        }
        Group group;
        group.demand = level + 1;
        for (std::size_t k = begin; k < end; ++k) {
          group.children.push_back(ready[k]);
          group.bounds.extend(groups[std::size_t(ready[k])].bounds);
        }
        groups.push_back(std::move(group));
        next.push_back(int(groups.size() - 1));
      }
      ready = std::move(next);
    }
    ++level;
  }
}

// Each group's distance from the root, in nodes.
void placeGroups(const std::vector<Group>& groups, int group, int above, std::vector<int>& place) {
  place[std::size_t(group)] = above;
  for (int child : groups[std::size_t(group)].children) placeGroups(groups, child, above + 1, place);
}

std::uint32_t emitGroup(const std::vector<Group>& groups, int group, const std::vector<std::uint32_t>& objectRoots,
                        const glm::dvec3& origin, double margin, std::vector<Texel>& texels) {
  if (std::size_t(group) < objectRoots.size()) return objectRoots[std::size_t(group)];
  const std::uint32_t node = appendNode(texels);
  const std::vector<int>& children = groups[std::size_t(group)].children;
  for (std::size_t slot = 0; slot < children.size(); ++slot) {
    const std::uint32_t child = emitGroup(groups, children[slot], objectRoots, origin, margin, texels);
    writeChild(texels, node, slot, groups[std::size_t(children[slot])].bounds, child, origin, margin);
  }
  return node;
}

std::vector<Group> objectGroups(const std::vector<TopLevelObject>& objects) {
  std::vector<Group> groups;
  for (const TopLevelObject& object : objects)
    groups.push_back(
        {object.bvh->nodes().empty() ? scene::Aabb() : object.bvh->nodes()[0].bounds, minimalDepth(object), {}});
  return groups;
}

}  // namespace

int wideLevels(std::uint64_t patches) {
  int levels = 1;
  for (std::uint64_t capacity = 4; capacity < patches; capacity *= 4) ++levels;
  return levels;
}

TopLevels buildTopLevels(const std::vector<TopLevelObject>& objects, const glm::dvec3& origin, double margin,
                         std::vector<Texel>& texels) {
  TopLevels top;
  if (objects.empty()) {
    top.root = appendNode(texels);
    top.depth = 1;
    return top;
  }
  std::vector<Group> groups = objectGroups(objects);
  const int root = groupObjects(groups);
  std::vector<int> place(groups.size(), 0);
  placeGroups(groups, root, 0, place);
  std::vector<std::uint32_t> objectRoots;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const TopLevelObject& object = objects[i];
    const int quadtree = object.bvh->leafPatches().empty() ? 0 : int(object.quadtreeLevels);
    // The levels this object may take: what the stack holds, less the
    // groups above it and its quadtrees below.
    Collapse collapse(object, int(gpu_layout::FACET_BVH4_MAX_DEPTH) - place[i] - quadtree, origin, margin, texels);
    objectRoots.push_back(collapse.run());
    top.depth = std::max(top.depth, place[i] + collapse.depth() + quadtree);
    top.patchSlots.push_back(collapse.patchSlots());
  }
  top.root = emitGroup(groups, root, objectRoots, origin, margin, texels);
  return top;
}

}  // namespace facet::gpu_backend

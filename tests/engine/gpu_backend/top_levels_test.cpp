// The top levels of the GPU's 4-wide BVH (engine/gpu_backend/top_levels.h):
// within the traversal's stack on inputs that defeat the SAH, every patch
// reached once through boxes that hold it, and the objects' grouping as
// deep as Kraft's inequality says and no deeper.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "engine/gpu_backend/top_levels.h"
#include "tests/support/degenerate_cages.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;
using scene::testing::Degenerate;

struct Object {
  scene::SubdivisionSurface surface;
  scene::PatchBvh bvh;
};

Object degenerateObject(Degenerate kind, int quads) {
  Object object{scene::testing::degenerateSurface(kind, quads), {}};
  object.bvh = scene::PatchBvh::build(object.surface);
  return object;
}

TopLevelObject topLevelObject(const Object& object, std::uint32_t quadtreeLevels) {
  TopLevelObject top;
  top.bvh = &object.bvh;
  top.quadtreeLevels = quadtreeLevels;
  top.nodesPerPatch = ((1u << (2 * quadtreeLevels)) - 1) / 3;
  for (int source : object.bvh.leafPatches())
    top.patchBounds.push_back(scene::patchBounds(object.surface.bezierPatch(source)));
  return top;
}

float box(const std::vector<Texel>& texels, std::uint32_t node, int texel, std::size_t slot) {
  return std::bit_cast<float>(texels[std::size_t(node) * layout::FACET_BVH4_TEXELS + std::size_t(texel)][slot]);
}

// Walks the nodes from the root: every patch of every object reached once,
// inside each box on its way (origin 0, no margin); returns the longest path
// of nodes, each patch's quadtree levels added.
int walk(const std::vector<TopLevelObject>& objects, const TopLevels& top, const std::vector<Texel>& texels) {
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> patchSlots;  // -> object
  for (std::size_t i = 0; i < top.patchSlots.size(); ++i)
    for (const auto& slot : top.patchSlots[i]) patchSlots[slot] = i;
  std::vector<std::vector<int>> reached(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) reached[i].assign(objects[i].patchBounds.size(), 0);
  struct Visit {
    std::uint32_t node;
    int depth;
    std::vector<scene::Aabb> path;
  };
  std::vector<Visit> stack{{top.root, 1, {}}};
  int deepest = 0;
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, visit.depth);
    const std::size_t references = std::size_t(visit.node) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES;
    for (std::size_t slot = 0; slot < 4; ++slot) {
      const std::uint32_t reference = texels[references][slot];
      if (reference == layout::FACET_BVH4_EMPTY) continue;
      scene::Aabb childBox;
      for (int axis = 0; axis < 3; ++axis) {
        childBox.lo[axis] = box(texels, visit.node, 2 * axis, slot);
        childBox.hi[axis] = box(texels, visit.node, 2 * axis + 1, slot);
      }
      std::vector<scene::Aabb> path = visit.path;
      path.push_back(childBox);
      const auto patchSlot = patchSlots.find({references, slot});
      if (patchSlot == patchSlots.end()) {
        stack.push_back({reference, visit.depth + 1, path});
        continue;
      }
      const TopLevelObject& object = objects[patchSlot->second];
      const std::uint32_t patch = reference / object.nodesPerPatch;
      EXPECT_EQ(reference % object.nodesPerPatch, 0u);
      ++reached[patchSlot->second][patch];
      deepest = std::max(deepest, visit.depth + int(object.quadtreeLevels));
      const scene::Aabb& hull = object.patchBounds[patch];
      for (const scene::Aabb& b : path)
        for (int axis = 0; axis < 3; ++axis) {
          EXPECT_LE(b.lo[axis], hull.lo[axis]);
          EXPECT_GE(b.hi[axis], hull.hi[axis]);
        }
    }
  }
  for (const std::vector<int>& counts : reached)
    for (int count : counts) EXPECT_EQ(count, 1);
  return deepest;
}

class DegenerateTopLevels : public ::testing::TestWithParam<Degenerate> {};

// The binary BVH of these is up to kMaxDepth deep; with the finest quadtrees
// (a dicing rate of 256: 8 levels) and sixteen objects above, the collapse
// must quarter runs of patches to stay within the stack.
TEST_P(DegenerateTopLevels, FitTheTraversalStack) {
  const Object object = degenerateObject(GetParam(), 3000);
  for (std::size_t copies : {std::size_t(1), std::size_t(16)}) {
    for (std::uint32_t levels : {1u, 8u}) {
      const std::vector<TopLevelObject> objects(copies, topLevelObject(object, levels));
      std::vector<Texel> texels;
      const TopLevels top = buildTopLevels(objects, glm::dvec3(0.0), 0.0, texels);
      const int depth = walk(objects, top, texels);
      EXPECT_EQ(depth, top.depth);
      EXPECT_LE(top.depth, int(layout::FACET_BVH4_MAX_DEPTH)) << copies << " objects, " << levels << " levels";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Inputs, DegenerateTopLevels,
                         ::testing::Values(Degenerate::AlongALine, Degenerate::AllInOnePoint,
                                           Degenerate::GeometricSizes, Degenerate::NestedSizes),
                         [](const auto& info) { return scene::testing::degenerateName(info.param); });

// One-patch objects need exactly one wide level and their quadtree's: the
// grouping over them is ceil(log4(sum 4^(1 + levels))) deep, up to the
// stack's 17 when four objects each need 16.
TEST(TopLevelGrouping, IsAsDeepAsKraftsInequalityAllows) {
  const Object one = degenerateObject(Degenerate::AlongALine, 1);
  const std::vector<std::vector<std::uint32_t>> cases = {
      {1}, {1, 1}, {3, 1, 1, 1, 1}, {2, 2, 2, 2, 2}, {5, 1, 1, 4, 4, 4, 4}, {15, 15, 15, 15}, {15, 14, 14, 14, 14, 1}};
  for (const std::vector<std::uint32_t>& levels : cases) {
    std::vector<TopLevelObject> objects;
    double kraft = 0.0;
    for (std::uint32_t l : levels) {
      objects.push_back(topLevelObject(one, l));
      kraft += std::pow(4.0, 1.0 + l);
    }
    std::vector<Texel> texels;
    const TopLevels top = buildTopLevels(objects, glm::dvec3(0.0), 0.0, texels);
    EXPECT_EQ(top.depth, int(std::ceil(std::log(kraft) / std::log(4.0) - 1e-9))) << levels.size() << " objects";
    EXPECT_EQ(walk(objects, top, texels), top.depth);
    EXPECT_LE(top.depth, int(layout::FACET_BVH4_MAX_DEPTH));
  }
}

}  // namespace
}  // namespace facet::gpu_backend

#include "scenes/patch_bvh.h"
#include "scenes/subdivision_surface.h"
#include "tests/support/cages.h"
#include "tests/support/degenerate_cages.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <random>
#include <string>

namespace facet::scene {
namespace {

using testing::loadTortureCage;
using testing::tortureCageNames;

bool contains(const Aabb& box, const glm::dvec3& p, double slack) {
  for (int axis = 0; axis < 3; ++axis)
    if (p[axis] < box.lo[axis] - slack || p[axis] > box.hi[axis] + slack) return false;
  return true;
}

bool contains(const Aabb& outer, const Aabb& inner) {
  return contains(outer, inner.lo, 0.0) && contains(outer, inner.hi, 0.0);
}

class BvhOfEachCage : public ::testing::TestWithParam<std::string> {};

// The convex-hull property the BVH and the exact intersector rely on: every
// surface point OpenSubdiv evaluates lies in the hull box of its patch and in
// the restricted hull of any sub-square holding it (Gregory patches included).
TEST_P(BvhOfEachCage, HullsEncloseTheLimitSurface) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  const double slack = 1e-12 * surface.bounds().diagonal();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 0; p < surface.patchCount(); ++p) {
    const BezierPatch& bezier = surface.bezierPatch(p);
    const PatchDomain& domain = surface.patch(p).domain;
    const Aabb whole = patchBounds(bezier);
    for (int sample = 0; sample < 8; ++sample) {
      double s0 = unit(random), s1 = unit(random), t0 = unit(random), t1 = unit(random);
      if (s0 > s1) std::swap(s0, s1);
      if (t0 > t1) std::swap(t0, t1);
      const Aabb piece = restrictBezierPatch(bezier, s0, s1, t0, t1).bounds();
      for (int k = 0; k < 4; ++k) {
        double s = s0 + (s1 - s0) * unit(random), t = t0 + (t1 - t0) * unit(random);
        glm::dvec3 point = surface.evaluatePatch(p, domain.u0 + s * domain.size, domain.v0 + t * domain.size).position;
        ASSERT_TRUE(contains(whole, point, slack)) << "patch " << p;
        ASSERT_TRUE(contains(piece, point, slack))
            << "patch " << p << " piece [" << s0 << "," << s1 << "]x[" << t0 << "," << t1 << "]";
      }
    }
  }
}

TEST_P(BvhOfEachCage, EveryPatchLiesInOneLeafWithinItsAncestors) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  PatchBvh bvh = PatchBvh::build(surface);
  const auto& nodes = bvh.nodes();
  ASSERT_FALSE(nodes.empty());

  // Every patch in exactly one leaf, leaves within their parents' bounds.
  std::vector<int> seen(surface.patchCount(), 0);
  for (int i = 0; i < static_cast<int>(nodes.size()); ++i) {
    const PatchBvh::Node& node = nodes[i];
    if (node.leaf()) {
      for (int k = 0; k < node.patchCount; ++k) {
        int patch = bvh.leafPatches()[node.next + k];
        ++seen[patch];
        EXPECT_TRUE(contains(node.bounds, patchBounds(surface.bezierPatch(patch))));
      }
    } else {
      ASSERT_GT(node.next, i + 1);
      EXPECT_TRUE(contains(node.bounds, nodes[i + 1].bounds));
      EXPECT_TRUE(contains(node.bounds, nodes[node.next].bounds));
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);

  EXPECT_NE(describe(bvh.statistics()).find("nodes"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(TortureCages, BvhOfEachCage, ::testing::ValuesIn(tortureCageNames()));

class DegenerateBvh : public ::testing::TestWithParam<testing::Degenerate> {};

// Inputs on which the SAH alone peels off a few patches per level: the build
// stays within kMaxDepth (halving at the median where the SAH would go
// deeper), keeps every patch in one leaf of at most four, and its recorded
// depth is the tree's.
TEST_P(DegenerateBvh, StaysWithinItsDepthBound) {
  for (int quads : {1, 5, 3000}) {
    const SubdivisionSurface surface = testing::degenerateSurface(GetParam(), quads);
    ASSERT_EQ(surface.patchCount(), quads);
    const PatchBvh bvh = PatchBvh::build(surface);
    const auto& nodes = bvh.nodes();
    std::vector<int> seen(std::size_t(quads), 0), depth(nodes.size(), 0);
    int deepest = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      deepest = std::max(deepest, depth[i]);
      if (nodes[i].leaf()) {
        EXPECT_LE(nodes[i].patchCount, 4);
        for (int k = 0; k < nodes[i].patchCount; ++k)
          ++seen[std::size_t(bvh.leafPatches()[std::size_t(nodes[i].next + k)])];
      } else {
        depth[i + 1] = depth[std::size_t(nodes[i].next)] = depth[i] + 1;
      }
    }
    for (int count : seen) EXPECT_EQ(count, 1);
    EXPECT_EQ(bvh.statistics().maxDepth, deepest);
    EXPECT_LE(deepest, PatchBvh::kMaxDepth) << quads << " quads";
  }
}

INSTANTIATE_TEST_SUITE_P(Inputs, DegenerateBvh,
                         ::testing::Values(testing::Degenerate::AlongALine, testing::Degenerate::AllInOnePoint,
                                           testing::Degenerate::GeometricSizes, testing::Degenerate::NestedSizes),
                         [](const auto& info) { return testing::degenerateName(info.param); });

}  // namespace
}  // namespace facet::scene

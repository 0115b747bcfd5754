#include "scenes/input_error.h"
#include "scenes/subdivision_surface.h"
#include "tests/support/cages.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace facet::scene {
namespace {

using testing::loadTortureCage;
using testing::tortureCageNames;

class SurfaceOfEachCage : public ::testing::TestWithParam<std::string> {};

// The Bézier form (what the GPU gets) is the same surface OpenSubdiv
// evaluates, for every patch kind: regular, boundary, corner, Gregory.
TEST_P(SurfaceOfEachCage, BezierFormMatchesOpenSubdivEvaluation) {
  for (EndCapBasis endCaps : {EndCapBasis::Gregory, EndCapBasis::BSpline}) {
    SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()), {3, endCaps});
    const double diagonal = surface.bounds().diagonal();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int p = 0; p < surface.patchCount(); ++p) {
      const PatchDomain& domain = surface.patch(p).domain;
      for (int sample = 0; sample < 12; ++sample) {
        // Corners and edges included: that is where boundary rules act.
        double s = sample < 4 ? (sample & 1) : unit(random), t = sample < 4 ? (sample >> 1) : unit(random);
        glm::dvec3 osd = surface.evaluatePatch(p, domain.u0 + s * domain.size, domain.v0 + t * domain.size).position;
        worst = std::max(worst, glm::length(evaluateBezierPatch(surface.bezierPatch(p), s, t).position - osd));
      }
    }
    EXPECT_LE(worst, 1e-12 * diagonal) << GetParam();
  }
}

// Derivatives against central differences of positions, on every patch
// kind (Gregory derivatives are the exact ones, see subdivision_surface.h).
TEST_P(SurfaceOfEachCage, DerivativesAreThoseOfThePositions) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  double worst = 0.0;
  for (int p = 0; p < surface.patchCount(); ++p) {
    const PatchDomain& domain = surface.patch(p).domain;
    const double h = 1e-5 * domain.size;
    for (int sample = 0; sample < 4; ++sample) {
      const double u = domain.u0 + unit(random) * domain.size, v = domain.v0 + unit(random) * domain.size;
      const LimitPoint point = surface.evaluatePatch(p, u, v);
      const glm::dvec3 du =
          (surface.evaluatePatch(p, u + h, v).position - surface.evaluatePatch(p, u - h, v).position) / (2 * h);
      const glm::dvec3 dv =
          (surface.evaluatePatch(p, u, v + h).position - surface.evaluatePatch(p, u, v - h).position) / (2 * h);
      const double scale = std::max(glm::length(point.du), glm::length(point.dv));
      worst = std::max({worst, glm::length(du - point.du) / scale, glm::length(dv - point.dv) / scale});
    }
  }
  EXPECT_LE(worst, 1e-6) << GetParam();
}

// Every ptex face not in a hole is tiled exactly by its patches, and
// Far::PatchMap finds the patch whose domain holds a face point.
TEST_P(SurfaceOfEachCage, PatchesTilePtexFacesAndPatchMapFindsThem) {
  ControlCage cage = loadTortureCage(GetParam());
  SubdivisionSurface surface = SubdivisionSurface::create(cage);
  std::map<int, double> area;
  for (int p = 0; p < surface.patchCount(); ++p) {
    const PatchInfo& info = surface.patch(p);
    area[info.ptexFace] += info.domain.size * info.domain.size;
  }
  int holePtexFaces = 0;
  for (int hole : cage.holes) holePtexFaces += cage.faceVertexCounts[hole] == 4 ? 1 : cage.faceVertexCounts[hole];
  EXPECT_EQ(static_cast<int>(area.size()), surface.statistics().ptexFaces - holePtexFaces);
  for (const auto& [face, covered] : area) EXPECT_DOUBLE_EQ(covered, 1.0) << "ptex face " << face;

  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const auto& [face, covered] : area) {
    for (int sample = 0; sample < 8; ++sample) {
      double u = unit(random), v = unit(random);
      std::optional<int> patch = surface.findPatch(face, u, v);
      ASSERT_TRUE(patch.has_value());
      const PatchDomain& domain = surface.patch(*patch).domain;
      EXPECT_EQ(surface.patch(*patch).ptexFace, face);
      EXPECT_TRUE(u >= domain.u0 && u <= domain.u0 + domain.size && v >= domain.v0 && v <= domain.v0 + domain.size);
    }
  }
}

// Transition bits (which crack-free dicing relies on) use the boundary's
// edge order and mean "the neighbour across is one level deeper"; checked
// wherever the neighbour lies in the same ptex face, where PatchMap finds it.
TEST_P(SurfaceOfEachCage, TransitionBitsMarkDeeperNeighbours) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  int checked = 0;
  for (int p = 0; p < surface.patchCount(); ++p) {
    const PatchInfo& info = surface.patch(p);
    const double u0 = info.domain.u0, v0 = info.domain.v0, f = info.domain.size, e = 1e-9;
    const double across[4][2] = {
        {u0 + f / 2, v0 - e}, {u0 + f + e, v0 + f / 2}, {u0 + f / 2, v0 + f + e}, {u0 - e, v0 + f / 2}};
    for (int edge = 0; edge < 4; ++edge) {
      const double u = across[edge][0], v = across[edge][1];
      if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) continue;
      std::optional<int> neighbour = surface.findPatch(info.ptexFace, u, v);
      if (!neighbour) continue;
      const bool deeper = surface.patch(*neighbour).depth == info.depth + 1;
      EXPECT_EQ(deeper, ((info.transitionMask >> edge) & 1u) != 0) << "patch " << p << " edge " << edge;
      EXPECT_LE(std::abs(surface.patch(*neighbour).depth - info.depth), 1);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

INSTANTIATE_TEST_SUITE_P(TortureCages, SurfaceOfEachCage, ::testing::ValuesIn(tortureCageNames()));

TEST(SubdivisionSurface, CountsPatchesAndReportsMemory) {
  SubdivisionSurface cube = SubdivisionSurface::create(loadTortureCage("cube"), {3});
  const SurfaceStatistics& stats = cube.statistics();
  EXPECT_EQ(stats.isolationLevel, 3);
  EXPECT_EQ(stats.cageFaces, 6);
  EXPECT_EQ(stats.ptexFaces, 6);
  // Each face corner is an extraordinary vertex: isolated to level 3, each
  // of the 24 face corners keeps one Gregory patch; the rest is regular.
  EXPECT_EQ(stats.endCapPatches, 24);
  EXPECT_EQ(stats.regularPatches + stats.endCapPatches, cube.patchCount());
  // Neighbouring Gregory patches share their edge points.
  EXPECT_GT(stats.localPoints, 0);
  EXPECT_LT(stats.localPoints, 24 * 20);
  EXPECT_GT(stats.openSubdivBytes, 0u);
  EXPECT_NE(describe(stats).find("patches"), std::string::npos);
}

TEST(SubdivisionSurface, SemiSharpCreasesRaiseTheIsolationLevel) {
  // creased_box has a crease of sharpness 2.5: isolation reaches level 3.
  EXPECT_EQ(SubdivisionSurface::create(loadTortureCage("creased_box"), {1}).statistics().isolationLevel, 3);
  EXPECT_EQ(SubdivisionSurface::create(loadTortureCage("creased_box"), {5}).statistics().isolationLevel, 5);
}

TEST(SubdivisionSurface, NonQuadFacesSplitIntoOnePtexFacePerCorner) {
  ControlCage cage = loadTortureCage("ngon_prism");
  int expected = 0;
  for (int count : cage.faceVertexCounts) expected += count == 4 ? 1 : count;
  SubdivisionSurface surface = SubdivisionSurface::create(cage);
  EXPECT_EQ(surface.statistics().ptexFaces, expected);
  // The hexagon is face 0: its six ptex faces map back to it.
  for (int p = 0; p < surface.patchCount(); ++p)
    if (surface.patch(p).ptexFace < 6) {
      EXPECT_EQ(surface.patch(p).coarseFace, 0);
    }
}

TEST(SubdivisionSurface, InfinitelySharpCreaseLoopKeepsAFlatFaceFlat) {
  // The bottom of creased_box: nine cage points at z = -1 inside an
  // infinitely sharp loop, so its limit is exactly the plane z = -1.
  ControlCage cage = loadTortureCage("creased_box");
  SubdivisionSurface surface = SubdivisionSurface::create(cage);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int bottomSamples = 0;
  for (int face = 0; face < cage.faceCount(); ++face) {
    bool bottom = true;
    for (int c = 0; c < 4; ++c) bottom = bottom && cage.positions[cage.faceVertexIndices[4 * face + c]].z == -1.0;
    if (!bottom) continue;
    for (int sample = 0; sample < 16; ++sample) {
      std::optional<LimitPoint> point = surface.evaluateFace(face, unit(random), unit(random));
      ASSERT_TRUE(point);
      EXPECT_NEAR(point->position.z, -1.0, 1e-12);
      ++bottomSamples;
    }
  }
  EXPECT_EQ(bottomSamples, 4 * 16);
}

TEST(SubdivisionSurface, BoundaryInterpolationOptionDecidesWhetherCornersAreInterpolated) {
  ControlCage cage = loadTortureCage("nearly_flat");
  const glm::dvec3 corner = cage.positions[0];  // a valence-2 boundary corner
  cage.options.boundary = BoundaryInterpolation::EdgeAndCorner;
  std::optional<LimitPoint> sharp = SubdivisionSurface::create(cage).evaluateFace(0, 0.0, 0.0);
  ASSERT_TRUE(sharp);
  EXPECT_LT(glm::length(sharp->position - corner), 1e-12);
  cage.options.boundary = BoundaryInterpolation::EdgeOnly;
  std::optional<LimitPoint> smooth = SubdivisionSurface::create(cage).evaluateFace(0, 0.0, 0.0);
  ASSERT_TRUE(smooth);
  EXPECT_GT(glm::length(smooth->position - corner), 0.1);
}

TEST(SubdivisionSurface, HolesHaveNoPatches) {
  ControlCage cage = loadTortureCage("boundary_hole");
  ASSERT_EQ(cage.holes, (std::vector<int>{5}));
  SubdivisionSurface surface = SubdivisionSurface::create(cage);
  EXPECT_FALSE(surface.findPatch(5, 0.5, 0.5).has_value());
  EXPECT_TRUE(surface.findPatch(6, 0.5, 0.5).has_value());
  for (int p = 0; p < surface.patchCount(); ++p) EXPECT_NE(surface.patch(p).coarseFace, 5);
}

// Cages built in code (not through the OBJ reader) are checked too:
// OpenSubdiv itself would take an out-of-range index without complaint.
TEST(SubdivisionSurface, RejectsBadCagesFromAnySource) {
  auto expectRule = [](const ControlCage& cage, const std::string& rule) {
    try {
      SubdivisionSurface::create(cage);
      FAIL() << "accepted a cage breaking '" << rule << "'";
    } catch (const InputError& error) {
      EXPECT_EQ(error.source(), "programmatic");
      EXPECT_EQ(error.line(), 0);
      EXPECT_EQ(error.rule(), rule);
    }
  };
  ControlCage good;
  good.source = "programmatic";
  good.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  good.faceVertexCounts = {4};
  good.faceVertexIndices = {0, 1, 2, 3};
  EXPECT_GT(SubdivisionSurface::create(good).patchCount(), 0);

  ControlCage cage = good;
  cage.faceVertexIndices = {0, 1, 2, 7};
  expectRule(cage, "index out of range");
  cage = good;
  cage.faceVertexCounts = {2, 2};
  expectRule(cage, "degenerate face");
  cage = good;
  cage.positions[2].y = std::nan("");
  expectRule(cage, "non-finite value");
  cage = good;
  cage.creases = {{0, 2, 1.0f}};
  expectRule(cage, "crease on a non-edge");
  cage = good;
  cage.holes = {1};
  expectRule(cage, "index out of range");
  cage = good;
  cage.faceVertexCounts.clear();
  cage.faceVertexIndices.clear();
  expectRule(cage, "empty cage");
}

// Non-manifold edges, vertices repeated within a face and vertices no face
// uses: OpenSubdiv refines them under either scheme, and so do we.
TEST(SubdivisionSurface, BuildsWhatOpenSubdivAccepts) {
  for (const char* name : {"nonmanifold_edge", "repeated_vertex", "bare_vertex"}) {
    const ControlCage cage = loadObjCage(std::string(FACET_TEST_DATA_DIR) + "/" + name + ".obj");
    for (Subdivision subdivision : {Subdivision::CatmullClark, Subdivision::None}) {
      const SubdivisionSurface surface = SubdivisionSurface::create(cage, {3, EndCapBasis::Gregory, subdivision});
      EXPECT_GT(surface.patchCount(), 0) << name;
      for (int p = 0; p < surface.patchCount(); ++p) {
        const PatchDomain& domain = surface.patch(p).domain;
        const LimitPoint centre =
            surface.evaluatePatch(p, domain.u0 + 0.5 * domain.size, domain.v0 + 0.5 * domain.size);
        const glm::dvec3 bezier = evaluateBezierPatch(surface.bezierPatch(p), 0.5, 0.5).position;
        EXPECT_LT(glm::length(centre.position - bezier), 1e-12 * surface.bounds().diagonal()) << name << " " << p;
      }
    }
  }
}

}  // namespace
}  // namespace facet::scene

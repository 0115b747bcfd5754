// Texture coordinates on the surface: OpenSubdiv's face-varying patches
// under the face-varying rules, their Bézier form (what the GPU evaluates)
// against OpenSubdiv's own evaluation, and the rules a cage's channel must
// keep; a second set and vertex colours subdivide as the first set does.
#include "scenes/input_error.h"
#include "scenes/obj_cage.h"
#include "scenes/subdivision_surface.h"
#include "tests/support/cages.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace facet::scene {
namespace {

using FV = FaceVaryingInterpolation;

ControlCage checkerCube(FV rule) {
  ControlCage cage = loadObjCage(std::string(FACET_TEST_DATA_DIR) + "/uv_checker_cube.obj");
  cage.options.faceVarying = rule;
  return cage;
}

struct SurfacePoint {
  glm::dvec3 position;
  LimitTexcoord texcoord;
};

SurfacePoint at(const SubdivisionSurface& surface, int ptexFace, double u, double v) {
  const std::optional<int> patch = surface.findPatch(ptexFace, u, v);
  EXPECT_TRUE(patch.has_value());
  return {surface.evaluatePatch(*patch, u, v).position, surface.evaluateTexcoord(*patch, u, v)};
}

// Corner k of a quad's ptex face, counter-clockwise from (0, 0).
constexpr double kCornerU[4] = {0, 1, 1, 0};
constexpr double kCornerV[4] = {0, 0, 1, 1};

glm::dvec2 authored(const ControlCage& cage, int face, int corner) {
  return cage.texcoords[std::size_t(cage.faceVertexTexcoords[std::size_t(4 * face + corner)])];
}

TEST(SubdivisionTexcoords, LinearEverywhereTheyAreBilinearOnEachFace) {
  for (Subdivision subdivision : {Subdivision::CatmullClark, Subdivision::None}) {
    const ControlCage cage = checkerCube(FV::All);
    const SubdivisionSurface surface = SubdivisionSurface::create(cage, {.subdivision = subdivision});
    ASSERT_TRUE(surface.hasTexcoords());
    for (int face = 0; face < cage.faceCount(); ++face) {
      glm::dvec2 mean(0.0);
      for (int k = 0; k < 4; ++k) {
        EXPECT_LT(glm::distance(at(surface, face, kCornerU[k], kCornerV[k]).texcoord.uv, authored(cage, face, k)),
                  1e-12)
            << "face " << face << " corner " << k;
        mean += 0.25 * authored(cage, face, k);
      }
      EXPECT_LT(glm::distance(at(surface, face, 0.5, 0.5).texcoord.uv, mean), 1e-12) << "face " << face;
    }
  }
}

TEST(SubdivisionTexcoords, AsAuthoredANonQuadFaceIsSplitAsItsPositionsAre) {
  ControlCage pentagon = testing::singleFace({{0, 0, 0}, {2, 0, 0}, {2.5, 1.5, 0}, {1, 2.5, 0}, {-0.5, 1.5, 0}});
  pentagon.texcoords = {{0, 0}, {1, 0}, {1, 0.7}, {0.5, 1}, {0, 0.6}};
  pentagon.faceVertexTexcoords = {0, 1, 2, 3, 4};
  const SubdivisionSurface surface = SubdivisionSurface::create(pentagon, {.subdivision = Subdivision::None});
  glm::dvec2 mean(0.0);
  for (const glm::dvec2& t : pentagon.texcoords) mean += t / 5.0;
  for (int k = 0; k < 5; ++k) {
    // Sub-face k: its vertex at (0, 0), the centroid at (1, 1).
    EXPECT_LT(glm::distance(at(surface, k, 0, 0).texcoord.uv, pentagon.texcoords[std::size_t(k)]), 1e-12);
    EXPECT_LT(glm::distance(at(surface, k, 1, 1).texcoord.uv, mean), 1e-12);
  }
}

TEST(SubdivisionTexcoords, UnderCornersOnlyIslandCornersKeepTheirValues) {
  const ControlCage cage = checkerCube(FV::CornersOnly);
  const SubdivisionSurface surface = SubdivisionSurface::create(cage);
  // Top and bottom are islands: each of their corners is a face-varying corner.
  for (int face : {0, 1})
    for (int k = 0; k < 4; ++k)
      EXPECT_LT(glm::distance(at(surface, face, kCornerU[k], kCornerV[k]).texcoord.uv, authored(cage, face, k)), 1e-12)
          << "face " << face << " corner " << k;
  // Smooth rules move them: the island's corners are no longer its values.
  const SubdivisionSurface smooth = SubdivisionSurface::create(checkerCube(FV::Smooth));
  EXPECT_GT(glm::distance(at(smooth, 1, 0, 0).texcoord.uv, authored(cage, 1, 0)), 1e-3);
}

TEST(SubdivisionTexcoords, AtTheSeamEachSideKeepsItsOwnCoordinates) {
  // The seam is the edge from vertex 0 to vertex 4: u = 0 of face 2's ptex
  // face (its corners 0 and 3), v = 0 of face 4's (corners 0 and 1). The
  // strip's corners there are face-varying corners, so each side is the
  // straight line between its own two values.
  for (FV rule : {FV::CornersOnly, FV::CornersPlus1, FV::CornersPlus2, FV::Boundaries, FV::All}) {
    const SubdivisionSurface surface = SubdivisionSurface::create(checkerCube(rule));
    for (double a : {0.1, 0.35, 0.5, 0.8}) {
      const SurfacePoint front = at(surface, 2, 0.0, a), side = at(surface, 4, a, 0.0);
      EXPECT_LT(glm::distance(front.position, side.position), 1e-12);
      EXPECT_NEAR(front.texcoord.uv.x, 0.0, 1e-12) << int(rule) << " at " << a;
      EXPECT_NEAR(side.texcoord.uv.x, 1.0, 1e-12) << int(rule) << " at " << a;
    }
  }
}

TEST(SubdivisionTexcoords, AcrossAJoinedEdgeTheyAreContinuous) {
  // The edge from vertex 2 to vertex 6 joins face 3 (its corners 0 and 1,
  // v = 0) and face 4 (corners 3 and 2, v = 1), with one value per vertex on
  // both sides.
  for (FV rule : {FV::Smooth, FV::CornersOnly, FV::All}) {
    const SubdivisionSurface surface = SubdivisionSurface::create(checkerCube(rule));
    for (double a : {0.0, 0.2, 0.5, 0.9}) {
      const SurfacePoint one = at(surface, 3, a, 0.0), other = at(surface, 4, a, 1.0);
      EXPECT_LT(glm::distance(one.position, other.position), 1e-12);
      EXPECT_LT(glm::distance(one.texcoord.uv, other.texcoord.uv), 1e-12) << int(rule) << " at " << a;
    }
  }
}

// Without seams and under the smooth rule, texture coordinates refine as
// positions do, so an affine map of the positions stays that map of the
// limit surface, derivatives included: OpenSubdiv's face-varying patches
// and end caps against its vertex ones.
TEST(SubdivisionTexcoords, AnAffineMapOfThePositionsStaysAffineOnTheLimitSurface) {
  const auto map = [](const glm::dvec3& p) { return glm::dvec2(p.x + 0.5 * p.z + 0.25, p.y - 0.25 * p.x); };
  for (const std::string name : {"cube", "creased_box", "valence_3_to_10", "ngon_prism"}) {
    ControlCage cage = testing::loadTortureCage(name);
    for (const glm::dvec3& p : cage.positions) cage.texcoords.push_back(map(p));
    cage.faceVertexTexcoords = cage.faceVertexIndices;
    cage.options.faceVarying = FV::Smooth;
    for (EndCapBasis endCaps : {EndCapBasis::Gregory, EndCapBasis::BSpline}) {
      const SubdivisionSurface surface = SubdivisionSurface::create(cage, {.endCaps = endCaps});
      for (int patch = 0; patch < surface.patchCount(); ++patch) {
        const PatchDomain& d = surface.patch(patch).domain;
        for (double s : {0.0, 0.3, 1.0})
          for (double t : {0.0, 0.6, 1.0}) {
            const double u = d.u0 + s * d.size, v = d.v0 + t * d.size;
            const LimitPoint point = surface.evaluatePatch(patch, u, v);
            const LimitTexcoord texcoord = surface.evaluateTexcoord(patch, u, v);
            const double scale = glm::length(point.du) + glm::length(point.dv);
            ASSERT_LT(glm::distance(texcoord.uv, map(point.position)), 1e-12) << name << " patch " << patch;
            ASSERT_LT(glm::distance(texcoord.du, map(point.du) - map(glm::dvec3(0.0))), 1e-11 * scale)
                << name << " patch " << patch;
            ASSERT_LT(glm::distance(texcoord.dv, map(point.dv) - map(glm::dvec3(0.0))), 1e-11 * scale)
                << name << " patch " << patch;
          }
      }
    }
  }
}

// The Bézier form the GPU evaluates is OpenSubdiv's patch, and the
// derivatives are those of the coordinates (central differences).
TEST(SubdivisionTexcoords, TheBezierFormAndTheDerivativesAreOpenSubdivs) {
  for (FV rule : {FV::Smooth, FV::CornersOnly, FV::CornersPlus2, FV::Boundaries, FV::All})
    for (EndCapBasis endCaps : {EndCapBasis::Gregory, EndCapBasis::BSpline}) {
      const SubdivisionSurface surface = SubdivisionSurface::create(checkerCube(rule), {.endCaps = endCaps});
      for (int patch = 0; patch < surface.patchCount(); ++patch) {
        const PatchDomain& d = surface.patch(patch).domain;
        for (double s : {0.0, 0.25, 0.7, 1.0})
          for (double t : {0.0, 0.4, 0.9, 1.0}) {
            const double u = d.u0 + s * d.size, v = d.v0 + t * d.size;
            const LimitTexcoord oracle = surface.evaluateTexcoord(patch, u, v);
            const BezierSample bezier = evaluateBezierPatch(*surface.texcoordPatch(patch), s, t);
            ASSERT_LT(glm::distance(glm::dvec2(bezier.position), oracle.uv), 1e-12) << "patch " << patch;
            ASSERT_LT(glm::distance(glm::dvec2(bezier.du) / d.size, oracle.du), 1e-9) << "patch " << patch;
            ASSERT_LT(glm::distance(glm::dvec2(bezier.dv) / d.size, oracle.dv), 1e-9) << "patch " << patch;
          }
        const double h = 1e-6 * d.size, u = d.u0 + 0.45 * d.size, v = d.v0 + 0.55 * d.size;
        const LimitTexcoord centre = surface.evaluateTexcoord(patch, u, v);
        const glm::dvec2 du =
            (surface.evaluateTexcoord(patch, u + h, v).uv - surface.evaluateTexcoord(patch, u - h, v).uv) / (2 * h);
        const glm::dvec2 dv =
            (surface.evaluateTexcoord(patch, u, v + h).uv - surface.evaluateTexcoord(patch, u, v - h).uv) / (2 * h);
        const double scale = 1.0 + glm::length(centre.du) + glm::length(centre.dv);
        ASSERT_LT(glm::distance(du, centre.du), 1e-6 * scale) << "patch " << patch;
        ASSERT_LT(glm::distance(dv, centre.dv), 1e-6 * scale) << "patch " << patch;
      }
    }
}

TEST(SubdivisionTexcoords, ACageWithoutThemHasNone) {
  const SubdivisionSurface surface = SubdivisionSurface::create(testing::loadTortureCage("cube"));
  EXPECT_FALSE(surface.hasTexcoords());
  EXPECT_EQ(surface.texcoordPatch(0), nullptr);
  EXPECT_EQ(surface.evaluateTexcoord(0, 0.5, 0.5).uv, glm::dvec2(0.0));
}

void expectRejected(const ControlCage& cage, const std::string& rule) {
  try {
    SubdivisionSurface::create(cage);
    ADD_FAILURE() << "accepted a cage breaking '" << rule << "'";
  } catch (const InputError& error) {
    EXPECT_EQ(error.rule(), rule) << error.what();
  }
}

TEST(SubdivisionTexcoords, AChannelThatBreaksItsRulesIsRejected) {
  const ControlCage good = checkerCube(FV::All);
  ControlCage shortIndices = good;
  shortIndices.faceVertexTexcoords.pop_back();
  expectRejected(shortIndices, "texture coordinates");
  ControlCage outOfRange = good;
  outOfRange.faceVertexTexcoords[5] = int(good.texcoords.size());
  expectRejected(outOfRange, "index out of range");
  outOfRange.faceVertexTexcoords[5] = -1;
  expectRejected(outOfRange, "index out of range");
  ControlCage notFinite = good;
  notFinite.texcoords[3].y = std::nan("");
  expectRejected(notFinite, "non-finite value");
  ControlCage unused = good;
  unused.faceVertexTexcoords.clear();
  expectRejected(unused, "texture coordinates");
}

// Colours and a second set are channels of their own, subdivided by the
// same rule: each equal to the first set's values evaluates as it does, and
// each is held to the channel rules under its own name.
TEST(SubdivisionChannels, EveryChannelSubdividesAsTheTextureCoordinates) {
  for (FV rule : {FV::All, FV::Smooth}) {
    ControlCage cage = checkerCube(rule);
    cage.texcoords1 = cage.texcoords;
    cage.faceVertexTexcoords1 = cage.faceVertexTexcoords;
    for (const glm::dvec2& t : cage.texcoords) cage.colors.push_back(glm::dvec3(t, 0.25));
    cage.faceVertexColors = cage.faceVertexTexcoords;
    const SubdivisionSurface surface = SubdivisionSurface::create(cage);
    ASSERT_TRUE(surface.hasChannel(Channel::Texcoord1));
    ASSERT_TRUE(surface.hasChannel(Channel::Color));
    double worst = 0.0;
    for (int patch = 0; patch < surface.patchCount(); ++patch) {
      const PatchDomain& d = surface.patch(patch).domain;
      for (double s : {0.1, 0.5, 0.9}) {
        const double u = d.u0 + s * d.size, v = d.v0 + (1.0 - s) * d.size;
        const LimitTexcoord first = surface.evaluateTexcoord(patch, u, v);
        const LimitTexcoord second = surface.evaluateTexcoord(patch, u, v, 1);
        worst = std::max({worst, glm::distance(first.uv, second.uv), glm::distance(first.du, second.du),
                          glm::distance(glm::dvec3(first.uv, 0.25), surface.evaluateColor(patch, u, v))});
      }
    }
    EXPECT_LT(worst, 1e-12);
  }
  // Without colours the colour is white.
  const SubdivisionSurface plain = SubdivisionSurface::create(checkerCube(FV::All));
  EXPECT_FALSE(plain.hasChannel(Channel::Color));
  EXPECT_EQ(plain.evaluateColor(0, 0.5, 0.5), glm::dvec3(1.0));
  ControlCage shortColours = checkerCube(FV::All);
  shortColours.colors.assign(3, glm::dvec3(0.5));
  shortColours.faceVertexColors.assign(shortColours.faceVertexIndices.size() - 1, 0);
  expectRejected(shortColours, "vertex colours");
  ControlCage unusedSecond = checkerCube(FV::All);
  unusedSecond.texcoords1 = unusedSecond.texcoords;
  expectRejected(unusedSecond, "second texture coordinates");
}

}  // namespace
}  // namespace facet::scene

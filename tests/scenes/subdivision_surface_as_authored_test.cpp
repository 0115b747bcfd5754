// Subdivision::None: the polygons as authored, held to the bilinear surface
// written out here from the cage alone.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/subdivision_surface.h"
#include "tests/support/cages.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>

namespace facet::scene {
namespace {

using testing::loadTortureCage;
using testing::singleFace;
using testing::tortureCageNames;

const RefinementSettings kAsAuthored{3, EndCapBasis::Gregory, Subdivision::None};

// The four points, counter-clockwise from (u, v) = (0, 0), of the bilinear
// patch over ptex face `k` of `face`: a quad's own corners; for any other
// face corner k, the midpoint of the edge after it, the centroid and the
// midpoint of the edge before it.
std::array<glm::dvec3, 4> expectedCorners(const ControlCage& cage, int face, int k) {
  std::size_t first = 0;
  for (int f = 0; f < face; ++f) first += std::size_t(cage.faceVertexCounts[std::size_t(f)]);
  const int count = cage.faceVertexCounts[std::size_t(face)];
  auto corner = [&](int i) {
    return cage.positions[std::size_t(cage.faceVertexIndices[first + std::size_t((i + count) % count)])];
  };
  if (count == 4) return {corner(0), corner(1), corner(2), corner(3)};
  glm::dvec3 centroid(0.0);
  for (int i = 0; i < count; ++i) centroid += corner(i);
  centroid /= double(count);
  return {corner(k), 0.5 * (corner(k) + corner(k + 1)), centroid, 0.5 * (corner(k - 1) + corner(k))};
}

LimitPoint bilinear(const std::array<glm::dvec3, 4>& p, double u, double v) {
  LimitPoint point;
  point.position = (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
  point.du = (1 - v) * (p[1] - p[0]) + v * (p[2] - p[3]);
  point.dv = (1 - u) * (p[3] - p[0]) + u * (p[2] - p[1]);
  return point;
}

// (face, k) of every ptex face, in ptex order.
std::vector<std::pair<int, int>> ptexFaces(const ControlCage& cage) {
  std::vector<std::pair<int, int>> faces;
  for (int face = 0; face < cage.faceCount(); ++face) {
    const int count = cage.faceVertexCounts[std::size_t(face)];
    for (int k = 0; k < (count == 4 ? 1 : count); ++k) faces.push_back({face, k});
  }
  return faces;
}

double distance(const LimitPoint& a, const LimitPoint& b) {
  return std::max({glm::length(a.position - b.position), glm::length(a.du - b.du), glm::length(a.dv - b.dv)});
}

class PolygonsOfEachCage : public ::testing::TestWithParam<std::string> {};

// One patch per ptex face, over all of it, evaluating (by OpenSubdiv and in
// Bézier form) to that face's bilinear patch, derivatives included.
TEST_P(PolygonsOfEachCage, EachPtexFaceIsItsBilinearPatch) {
  const ControlCage cage = loadTortureCage(GetParam());
  const SubdivisionSurface surface = SubdivisionSurface::create(cage, kAsAuthored);
  const std::vector<std::pair<int, int>> faces = ptexFaces(cage);
  const std::set<int> holes(cage.holes.begin(), cage.holes.end());
  int expectedPatches = 0;
  for (const auto& [face, k] : faces) expectedPatches += holes.count(face) ? 0 : 1;

  const SurfaceStatistics& stats = surface.statistics();
  EXPECT_EQ(stats.subdivision, Subdivision::None);
  EXPECT_EQ(stats.isolationLevel, 0);
  EXPECT_EQ(stats.ptexFaces, int(faces.size()));
  EXPECT_EQ(stats.regularPatches, expectedPatches);
  EXPECT_EQ(stats.endCapPatches, 0);
  EXPECT_EQ(stats.localPoints, 0);
  ASSERT_EQ(surface.patchCount(), expectedPatches);

  const double tolerance = 1e-12 * surface.bounds().diagonal();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::set<int> seen;
  for (int p = 0; p < surface.patchCount(); ++p) {
    const PatchInfo& info = surface.patch(p);
    ASSERT_TRUE(seen.insert(info.ptexFace).second) << "ptex face " << info.ptexFace << " has two patches";
    const auto [face, k] = faces[std::size_t(info.ptexFace)];
    EXPECT_EQ(info.coarseFace, face);
    EXPECT_EQ(info.domain.u0, 0.0);
    EXPECT_EQ(info.domain.v0, 0.0);
    EXPECT_EQ(info.domain.size, 1.0);
    EXPECT_EQ(info.boundaryMask, 0u);
    EXPECT_FALSE(info.gregory);
    const std::array<glm::dvec3, 4> corners = expectedCorners(cage, face, k);
    for (int sample = 0; sample < 12; ++sample) {
      const double u = sample < 4 ? (sample & 1) : unit(random), v = sample < 4 ? (sample >> 1) : unit(random);
      const LimitPoint expected = bilinear(corners, u, v);
      EXPECT_LE(distance(surface.evaluatePatch(p, u, v), expected), tolerance) << "patch " << p;
      const BezierSample bezier = evaluateBezierPatch(surface.bezierPatch(p), u, v);
      EXPECT_LE(distance({bezier.position, bezier.du, bezier.dv}, expected), tolerance) << "patch " << p;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(TortureCages, PolygonsOfEachCage, ::testing::ValuesIn(tortureCageNames()));

TEST(Polygons, ATriangleIsExactlyTheFlatTriangle) {
  const glm::dvec3 a(0.3, -1.2, 0.7), b(2.1, 0.4, -0.5), c(-0.6, 1.7, 1.9);
  const SubdivisionSurface surface = SubdivisionSurface::create(singleFace({a, b, c}), kAsAuthored);
  ASSERT_EQ(surface.patchCount(), 3);
  const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
  const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
  auto barycentric = [&](const glm::dvec3& p) {
    const double wb = glm::dot(glm::cross(p - a, c - a), normal) / (2 * area);
    const double wc = glm::dot(glm::cross(b - a, p - a), normal) / (2 * area);
    return glm::dvec3(1 - wb - wc, wb, wc);
  };
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double coveredArea = 0;
  for (int p = 0; p < surface.patchCount(); ++p) {
    // Each patch starts at its corner of the triangle and ends at the centroid.
    EXPECT_LT(glm::length(surface.evaluatePatch(p, 0, 0).position - std::array{a, b, c}[std::size_t(p)]), 1e-12);
    EXPECT_LT(glm::length(surface.evaluatePatch(p, 1, 1).position - (a + b + c) / 3.0), 1e-12);
    for (int sample = 0; sample < 64; ++sample) {
      const LimitPoint point = surface.evaluatePatch(p, unit(random), unit(random));
      EXPECT_LT(std::abs(glm::dot(point.position - a, normal)), 1e-12);
      const glm::dvec3 w = barycentric(point.position);
      EXPECT_GE(std::min({w.x, w.y, w.z}), -1e-12);
      EXPECT_LT(glm::length(glm::normalize(glm::cross(point.du, point.dv)) - normal), 1e-12);
    }
    // A planar bilinear patch is the quadrilateral through its corners.
    const glm::dvec3 p00 = surface.evaluatePatch(p, 0, 0).position, p10 = surface.evaluatePatch(p, 1, 0).position,
                     p11 = surface.evaluatePatch(p, 1, 1).position, p01 = surface.evaluatePatch(p, 0, 1).position;
    coveredArea += 0.5 * glm::length(glm::cross(p11 - p00, p01 - p10));
  }
  // The three quads tile the triangle: inside it, and of its area.
  EXPECT_NEAR(coveredArea, area, 1e-12);
}

TEST(Polygons, AQuadIsOneBilinearPatchThroughItsCorners) {
  // Twisted: corner 2 lifted out of the plane of the other three.
  const std::array<glm::dvec3, 4> corners = {glm::dvec3(0, 0, 0), glm::dvec3(2, 0.1, 0), glm::dvec3(1.8, 1.5, 0.9),
                                             glm::dvec3(-0.2, 1.1, 0.1)};
  const SubdivisionSurface surface =
      SubdivisionSurface::create(singleFace({corners.begin(), corners.end()}), kAsAuthored);
  ASSERT_EQ(surface.patchCount(), 1);
  EXPECT_EQ(surface.patch(0).ptexFace, 0);
  EXPECT_EQ(surface.patch(0).depth, 0);
  EXPECT_EQ(surface.patch(0).transitionMask, 0u);
  for (double u : {0.0, 0.25, 0.5, 1.0})
    for (double v : {0.0, 0.4, 1.0})
      EXPECT_LE(distance(surface.evaluatePatch(0, u, v), bilinear(corners, u, v)), 1e-12);
  EXPECT_NE(describe(surface.statistics()).find("as authored: 1 bilinear patches"), std::string::npos);
}

// A quad beside a split face keeps OpenSubdiv's transition bit on their
// shared edge, so dicing the quad places a vertex where its neighbours'
// corners meet, at the edge midpoint.
TEST(Polygons, AQuadBesideATriangleMarksTheSharedEdge) {
  ControlCage cage = singleFace({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}});
  cage.faceVertexCounts = {4, 3};
  cage.faceVertexIndices = {0, 1, 2, 3, 1, 4, 2};
  const SubdivisionSurface surface = SubdivisionSurface::create(cage, kAsAuthored);
  ASSERT_EQ(surface.patchCount(), 4);
  for (int p = 0; p < surface.patchCount(); ++p) {
    const PatchInfo& info = surface.patch(p);
    EXPECT_EQ(info.transitionMask, info.coarseFace == 0 ? 2u : 0u) << "patch " << p;  // 2: the edge u = 1
  }
  EXPECT_LT(glm::length(surface.evaluatePatch(0, 1, 0.5).position - glm::dvec3(1, 0.5, 0)), 1e-12);
  EXPECT_LT(glm::length(surface.evaluatePatch(1, 0, 1).position - glm::dvec3(1, 0.5, 0)), 1e-12);
}

TEST(Polygons, ATriangleMeshHasItsFaceNormals) {
  const Scene scene = loadScene(std::string(FACET_TEST_DATA_DIR) + "/faceted_gem.gltf");
  ASSERT_EQ(scene.objects.size(), 1u);
  const ControlCage& cage = scene.objects[0].cage;
  ASSERT_EQ(cage.faceVertexCounts, std::vector<int>(12, 3));
  const SubdivisionSurface surface = SubdivisionSurface::create(cage, kAsAuthored);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 0; p < surface.patchCount(); ++p) {
    const int* corner = &cage.faceVertexIndices[std::size_t(3 * surface.patch(p).coarseFace)];
    const glm::dvec3 a = cage.positions[std::size_t(corner[0])], b = cage.positions[std::size_t(corner[1])],
                     c = cage.positions[std::size_t(corner[2])];
    const glm::dvec3 faceNormal = glm::normalize(glm::cross(b - a, c - a));
    EXPECT_GT(glm::dot(faceNormal, a), 0.0);  // outwards: the gem is convex around the origin
    for (int sample = 0; sample < 16; ++sample) {
      const LimitPoint point = surface.evaluatePatch(p, unit(random), unit(random));
      EXPECT_LT(glm::length(glm::normalize(glm::cross(point.du, point.dv)) - faceNormal), 1e-12) << "patch " << p;
    }
  }
}

// A triangle's split quads carry its corners' normals, the normalized sums
// of two at the edge midpoints and of all three at the centroid, in the
// order of their points (counter-clockwise from (0, 0)).
TEST(Polygons, AuthoredNormalsFollowTheSplitOfTheFace) {
  const glm::dvec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  ControlCage cage = singleFace({a, b, c});
  const std::array<glm::dvec3, 3> normals = {glm::normalize(glm::dvec3(-0.3, -0.2, 1)),
                                             glm::normalize(glm::dvec3(0.4, -0.1, 1)),
                                             glm::normalize(glm::dvec3(0, 0.5, 1))};
  cage.faceVertexNormals = {normals.begin(), normals.end()};
  const SubdivisionSurface surface = SubdivisionSurface::create(cage, kAsAuthored);
  const glm::dvec3 centroid = glm::normalize(normals[0] + normals[1] + normals[2]);
  for (int p = 0; p < surface.patchCount(); ++p) {
    const std::array<glm::dvec3, 4>* corners = surface.authoredNormals(p);
    ASSERT_NE(corners, nullptr);
    const std::size_t k = std::size_t(p);
    EXPECT_LT(glm::length((*corners)[0] - normals[k]), 1e-12) << "patch " << p;
    EXPECT_LT(glm::length((*corners)[2] - centroid), 1e-12) << "patch " << p;
    // Its other two corners lie on the edges through its vertex.
    const glm::dvec3 next = glm::normalize(normals[k] + normals[(k + 1) % 3]);
    const glm::dvec3 previous = glm::normalize(normals[k] + normals[(k + 2) % 3]);
    const bool either = (glm::length((*corners)[1] - next) < 1e-12 && glm::length((*corners)[3] - previous) < 1e-12) ||
                        (glm::length((*corners)[1] - previous) < 1e-12 && glm::length((*corners)[3] - next) < 1e-12);
    EXPECT_TRUE(either) << "patch " << p;
  }
  // Subdivided, the authored normals do not apply.
  EXPECT_EQ(SubdivisionSurface::create(cage).authoredNormals(0), nullptr);
  // One normal per face corner, or an error naming the rule.
  cage.faceVertexNormals.pop_back();
  EXPECT_THROW(SubdivisionSurface::create(cage, kAsAuthored), InputError);
}

}  // namespace
}  // namespace facet::scene

// MikkTSpace tangents: along dP/du in each corner's tangent plane, the sign
// giving dP/dv's side, continuous across triangles that share a vertex,
// angle-weighted where they disagree, and split only at seams and mirrors.
#include "scenes/mikktspace.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace facet::scene {
namespace {

using UvMap = std::function<glm::dvec2(const glm::dvec3&)>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kTight = 1e-12;

glm::dvec3 xyz(const glm::dvec4& v) { return glm::dvec3(v); }

void addTriangle(std::vector<TangentCorner>& corners, const std::vector<glm::dvec3>& points, const UvMap& uv,
                 const glm::dvec3& normal = {0, 0, 1}) {
  for (const glm::dvec3& p : points) corners.push_back({p, normal, uv(p)});
}

// The unit square in z = 0, normal +z, as two counter-clockwise triangles.
std::vector<TangentCorner> flatQuad(const UvMap& uv) {
  std::vector<TangentCorner> corners;
  addTriangle(corners, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, uv);
  addTriangle(corners, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, uv);
  return corners;
}

void expectTangent(const glm::dvec4& tangent, const glm::dvec3& direction, double w) {
  EXPECT_NEAR(tangent.x, direction.x, kTight);
  EXPECT_NEAR(tangent.y, direction.y, kTight);
  EXPECT_NEAR(tangent.z, direction.z, kTight);
  EXPECT_EQ(tangent.w, w);
}

void expectInTangentPlane(const std::vector<TangentCorner>& corners, const std::vector<glm::dvec4>& tangents) {
  ASSERT_EQ(tangents.size(), corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    EXPECT_NEAR(glm::length(xyz(tangents[i])), 1.0, 1e-12) << "corner " << i;
    EXPECT_NEAR(glm::dot(xyz(tangents[i]), corners[i].normal), 0.0, 1e-12) << "corner " << i;
    EXPECT_TRUE(tangents[i].w == 1.0 || tangents[i].w == -1.0) << "corner " << i;
  }
}

TEST(Mikktspace, FlatQuadFollowsTheTextureAxes) {
  for (const glm::dvec4& t : mikktspaceTangents(flatQuad([](const glm::dvec3& p) { return glm::dvec2(p.x, p.y); })))
    expectTangent(t, {1, 0, 0}, 1.0);
  // Mirrored v: dP/du is unchanged, the bitangent flips.
  for (const glm::dvec4& t : mikktspaceTangents(flatQuad([](const glm::dvec3& p) { return glm::dvec2(p.x, -p.y); })))
    expectTangent(t, {1, 0, 0}, -1.0);
  // Mirrored u: dP/du turns round, and w keeps the bitangent along +y.
  for (const glm::dvec4& t : mikktspaceTangents(flatQuad([](const glm::dvec3& p) { return glm::dvec2(-p.x, p.y); })))
    expectTangent(t, {-1, 0, 0}, -1.0);
}

// A deterministic stream of numbers in [-1, 1): the same meshes everywhere.
class Numbers {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return double(state_ >> 11) / double(1ull << 52) - 1.0;
  }

 private:
  std::uint64_t state_ = 12345;
};

// A jittered, bumpy grid with a random unit normal and texture coordinate at
// each vertex (so mirrored and turned triangles meet), plus triangles with
// no texture area, two corners at one position, and one edge shared by three.
std::vector<TangentCorner> irregularMesh(Numbers& numbers) {
  constexpr int kSide = 6;
  std::vector<TangentCorner> grid;
  for (int j = 0; j <= kSide; ++j)
    for (int i = 0; i <= kSide; ++i) {
      const glm::dvec3 p(i + 0.3 * numbers.next(), j + 0.3 * numbers.next(), 0.5 * numbers.next());
      const glm::dvec3 n = glm::normalize(glm::dvec3(numbers.next(), numbers.next(), 1.5 + numbers.next()));
      grid.push_back({p, n, {numbers.next(), numbers.next()}});
    }
  const auto at = [&](int i, int j) { return grid[std::size_t(j * (kSide + 1) + i)]; };
  std::vector<TangentCorner> corners;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      corners.insert(corners.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      corners.insert(corners.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  TangentCorner flat = at(2, 2);
  flat.texcoord = at(1, 1).texcoord;
  corners.insert(corners.end(), {at(1, 1), flat, at(0, 2)});      // no texture area
  corners.insert(corners.end(), {at(3, 3), at(3, 3), at(4, 4)});  // two corners at one position
  corners.insert(corners.end(), {at(1, 0), at(0, 0), at(5, 5)});  // edge (0,0)-(1,0) shared by three
  corners.insert(corners.end(), {at(0, 0), at(1, 0), at(4, 5)});
  corners.insert(corners.end(), {at(4, 1), at(4, 1), at(4, 1)});  // a single point
  return corners;
}

TEST(Mikktspace, TangentsAreUnitAndInTheTangentPlane) {
  Numbers numbers;
  for (int mesh = 0; mesh < 20; ++mesh) {
    const std::vector<TangentCorner> corners = irregularMesh(numbers);
    expectInTangentPlane(corners, mikktspaceTangents(corners));
  }
}

TEST(Mikktspace, RejectsCornersThatAreNotTriangles) {
  EXPECT_TRUE(mikktspaceTangents({}).empty());
  std::vector<TangentCorner> corners = flatQuad([](const glm::dvec3& p) { return glm::dvec2(p.x, p.y); });
  corners.pop_back();
  EXPECT_THROW(mikktspaceTangents(corners), std::invalid_argument);
}

// A latitude band of the unit sphere (the poles have no longitude
// direction), smooth normals, u the fraction of longitude: its seam at u = 0
// and u = 1 shares positions but not texture coordinates.
std::vector<TangentCorner> sphereBand(int columns, int rows) {
  const auto vertex = [&](int i, int j) {
    const double longitude = 2 * kPi * (i % columns) / columns;
    const double latitude = (-75.0 + 150.0 * j / rows) * kPi / 180.0;
    const glm::dvec3 p(std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude),
                       std::sin(latitude));
    return TangentCorner{p, p, {double(i) / columns, double(j) / rows}};
  };
  std::vector<TangentCorner> corners;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      corners.insert(corners.end(), {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      corners.insert(corners.end(), {vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  return corners;
}

TEST(Mikktspace, SphereTangentsFollowLongitudeAndAgreeAtSharedVertices) {
  constexpr int kColumns = 64;
  const std::vector<TangentCorner> corners = sphereBand(kColumns, 24);
  const std::vector<glm::dvec4> tangents = mikktspaceTangents(corners);
  expectInTangentPlane(corners, tangents);
  // Away from the seam the columns on either side of a vertex balance out;
  // on it a vertex sees one column only, whose chord is off its longitude by
  // up to half the column's angle.
  const double seamAllowance = 0.5 * 2 * kPi / kColumns;
  std::map<std::tuple<double, double, double, double, double>, glm::dvec4> byVertex;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const glm::dvec3 p = corners[i].position;
    const glm::dvec3 east = glm::normalize(glm::dvec3(-p.y, p.x, 0.0));
    const double u = corners[i].texcoord.x;
    const double allowed = u > 0.0 && u < 1.0 ? 1e-6 : seamAllowance;
    EXPECT_LT(std::acos(std::min(1.0, glm::dot(xyz(tangents[i]), east))), allowed) << "corner " << i;
    EXPECT_EQ(tangents[i].w, 1.0);
    const auto key = std::make_tuple(p.x, p.y, p.z, corners[i].texcoord.x, corners[i].texcoord.y);
    const auto [first, inserted] = byVertex.emplace(key, tangents[i]);
    if (!inserted) {
      EXPECT_EQ(first->second, tangents[i]) << "corner " << i << " differs from its vertex's";
    }
  }
}

TEST(Mikktspace, AveragesByTheAngleAtTheVertex) {
  std::vector<TangentCorner> corners;
  // 45 degrees at the origin, mapped u = x, v = y: dP/du = +x.
  addTriangle(corners, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, [](const glm::dvec3& p) { return glm::dvec2(p.x, p.y); });
  // 135 degrees, mapped u = y, v = 2y - x (agreeing along their shared edge):
  // dP/du = (2, 1, 0) / sqrt(5).
  addTriangle(corners, {{0, 0, 0}, {1, 1, 0}, {-1, 0, 0}},
              [](const glm::dvec3& p) { return glm::dvec2(p.y, 2 * p.y - p.x); });
  const std::vector<glm::dvec4> tangents = mikktspaceTangents(corners);
  const glm::dvec3 expected =
      glm::normalize(0.25 * kPi * glm::dvec3(1, 0, 0) + 0.75 * kPi * glm::dvec3(2, 1, 0) / std::sqrt(5.0));
  expectTangent(tangents[0], expected, 1.0);
  EXPECT_EQ(tangents[0], tangents[3]) << "one vertex, one tangent";
  expectTangent(tangents[1], {1, 0, 0}, 1.0);  // only the first triangle there
  expectTangent(tangents[5], glm::dvec3(2, 1, 0) / std::sqrt(5.0), 1.0);
}

// Two unit squares side by side, the left one mapped u = x, v = y and the
// right one by `rightUv`.
std::vector<TangentCorner> twoSquares(const UvMap& rightUv) {
  std::vector<TangentCorner> corners = flatQuad([](const glm::dvec3& p) { return glm::dvec2(p.x, p.y); });
  addTriangle(corners, {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}}, rightUv);
  addTriangle(corners, {{1, 0, 0}, {2, 1, 0}, {1, 1, 0}}, rightUv);
  return corners;
}

TEST(Mikktspace, SeamKeepsTwoTangents) {
  // Right square turned a quarter (u = y, v = 3 - x): on the shared edge its
  // texture coordinates differ from the left's.
  const std::vector<glm::dvec4> seam =
      mikktspaceTangents(twoSquares([](const glm::dvec3& p) { return glm::dvec2(p.y, 3 - p.x); }));
  for (int corner = 0; corner < 6; ++corner) expectTangent(seam[std::size_t(corner)], {1, 0, 0}, 1.0);
  for (int corner = 6; corner < 12; ++corner) expectTangent(seam[std::size_t(corner)], {0, 1, 0}, 1.0);
  // Sheared instead (u = x, v = y + x - 1), continuous across the edge: the
  // vertices there are shared and blend both squares.
  const std::vector<glm::dvec4> joined =
      mikktspaceTangents(twoSquares([](const glm::dvec3& p) { return glm::dvec2(p.x, p.y + p.x - 1); }));
  const glm::dvec3 onEdge = xyz(joined[1]);  // left square's corner at (1, 0, 0)
  EXPECT_EQ(joined[1], joined[6]);
  EXPECT_GT(onEdge.x, 0.9);
  EXPECT_LT(onEdge.y, -0.1) << "pulled toward the right square's (1, -1, 0)";
}

TEST(Mikktspace, MirroredHalfOfAFanGetsItsOwnGroup) {
  // Four quadrants around the origin mapped u = |x|, v = y: the two with
  // x < 0 are mirrored.
  const UvMap uv = [](const glm::dvec3& p) { return glm::dvec2(std::abs(p.x), p.y); };
  std::vector<TangentCorner> corners;
  addTriangle(corners, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, uv);
  addTriangle(corners, {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}}, uv);
  addTriangle(corners, {{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}}, uv);
  addTriangle(corners, {{0, 0, 0}, {0, -1, 0}, {1, 0, 0}}, uv);
  const std::vector<glm::dvec4> tangents = mikktspaceTangents(corners);
  for (int triangle : {0, 3})
    for (int c = 0; c < 3; ++c) expectTangent(tangents[std::size_t(3 * triangle + c)], {1, 0, 0}, 1.0);
  for (int triangle : {1, 2})
    for (int c = 0; c < 3; ++c) expectTangent(tangents[std::size_t(3 * triangle + c)], {-1, 0, 0}, -1.0);
  // Either way the bitangent is dP/dv = +y.
  for (const glm::dvec4& t : tangents) EXPECT_NEAR(t.w * glm::cross(glm::dvec3(0, 0, 1), xyz(t)).y, 1.0, kTight);
}

// A good triangle mapped by `uv`, and beside it across the edge from (1, 0)
// to (0, 1) a triangle whose third corner maps to that edge's midpoint:
// no texture area.
std::vector<TangentCorner> goodAndFlat(const UvMap& uv) {
  std::vector<TangentCorner> corners;
  addTriangle(corners, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, uv);
  addTriangle(corners, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, uv);
  corners[4].texcoord = 0.5 * (uv({1, 0, 0}) + uv({0, 1, 0}));
  return corners;
}

TEST(Mikktspace, TrianglesWithoutTextureAreaTakeTheirNeighboursTangent) {
  // u = y, v = -x: dP/du = +y, away from the axis the fallback would pick.
  const std::vector<glm::dvec4> plain =
      mikktspaceTangents(goodAndFlat([](const glm::dvec3& p) { return glm::dvec2(p.y, -p.x); }));
  expectTangent(plain[3], {0, 1, 0}, 1.0);
  expectTangent(plain[5], {0, 1, 0}, 1.0);
  EXPECT_EQ(plain[3], plain[1]);
  EXPECT_EQ(plain[5], plain[2]);
  // Mirrored (u = y, v = x): the flat triangle joins the mirrored group.
  const std::vector<glm::dvec4> mirrored =
      mikktspaceTangents(goodAndFlat([](const glm::dvec3& p) { return glm::dvec2(p.y, p.x); }));
  expectTangent(mirrored[3], {0, 1, 0}, -1.0);
  expectTangent(mirrored[5], {0, 1, 0}, -1.0);
  // Its third corner touches no good triangle.
  for (const std::vector<glm::dvec4>* tangents : {&plain, &mirrored}) {
    EXPECT_NEAR(glm::length(xyz((*tangents)[4])), 1.0, kTight);
    EXPECT_NEAR((*tangents)[4].z, 0.0, kTight);
    EXPECT_EQ((*tangents)[4].w, 1.0);
  }
}

TEST(Mikktspace, IsolatedTriangleWithoutTextureAreaGetsSomeTangentInItsPlane) {
  for (const glm::dvec3& normal : {glm::normalize(glm::dvec3(1, 1, 1)), glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0)}) {
    std::vector<TangentCorner> corners;
    for (const glm::dvec3& p : {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)})
      corners.push_back({p, normal, {0.25, 0.5}});
    const std::vector<glm::dvec4> tangents = mikktspaceTangents(corners);
    expectInTangentPlane(corners, tangents);
    for (const glm::dvec4& t : tangents) EXPECT_EQ(t.w, 1.0);
  }
}

TEST(Mikktspace, TrianglesWithTwoCornersAtOnePositionAreLeftOutAndCopy) {
  const UvMap uv = [](const glm::dvec3& p) { return glm::dvec2(p.y, -p.x); };
  std::vector<TangentCorner> corners;
  addTriangle(corners, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, uv);
  // Across the edge from (1, 0) to (0, 0), with a texture area of its own:
  // were it grouped it would pull both vertices' tangents toward -x.
  addTriangle(corners, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}, uv);
  corners[4].texcoord = {-0.3, 0.7};
  const std::vector<glm::dvec4> tangents = mikktspaceTangents(corners);
  for (int c = 0; c < 3; ++c) expectTangent(tangents[std::size_t(c)], {0, 1, 0}, 1.0);
  EXPECT_EQ(tangents[3], tangents[0]);
  EXPECT_EQ(tangents[5], tangents[1]);
  expectInTangentPlane(corners, tangents);
}

}  // namespace
}  // namespace facet::scene

#include "scenes/mikktspace.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace facet::scene {
namespace {

// The smallest magnitude that counts as an area or a direction. The reference
// tests against FLT_MIN in single precision; this is the double counterpart,
// so only exact (or underflowed) zeros fall through.
constexpr double kSmallestMagnitude = std::numeric_limits<double>::min();

// cos(180 degrees), genTangSpaceDefault's threshold: two triangles of a group
// part ways only where their derivatives point exactly opposite.
constexpr double kSplitCosine = -1.0;

bool nonZero(double x) { return std::abs(x) > kSmallestMagnitude; }

bool nonZero(const glm::dvec3& v) { return nonZero(v.x) || nonZero(v.y) || nonZero(v.z); }

// Scaled before squaring: vectors the test above calls nonzero can be small
// enough that their squared length underflows to zero.
double robustLength(const glm::dvec3& v) {
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0.0)) return largest;
  return largest * glm::length(v / largest);
}

// A vector without direction stays as it is (zero), as in the reference,
// so that it adds nothing to a sum and matches nothing in a comparison.
glm::dvec3 unitOrAsIs(const glm::dvec3& v) { return nonZero(v) ? v / robustLength(v) : v; }

glm::dvec3 inPlaneOf(const glm::dvec3& normal, const glm::dvec3& v) {
  return unitOrAsIs(v - glm::dot(normal, v) * normal);
}

// For corners the texture mapping gives no direction. The reference leaves
// (1, 0, 0) there whatever the normal; this keeps that axis where it is not
// the one most aligned with the normal, takes the least aligned axis
// otherwise, and makes it orthogonal to the normal, so every output tangent
// is a unit vector in the corner's tangent plane.
glm::dvec3 fallbackTangent(const glm::dvec3& normal) {
  const glm::dvec3 a = glm::abs(normal);
  glm::dvec3 axis(0.0, 0.0, 1.0);
  if (a.x <= a.y && a.x <= a.z)
    axis = glm::dvec3(1.0, 0.0, 0.0);
  else if (a.y <= a.z)
    axis = glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 tangent = inPlaneOf(normal, axis);
  return nonZero(tangent) ? tangent : axis;
}

// One triangle as the grouping sees it.
struct MappedTriangle {
  glm::dvec3 sDirection{0.0};                // unit dP/du; zero where the mapping gives none
  glm::dvec3 tDirection{0.0};                // unit dP/dv
  bool orientationPreserving = false;        // positive texture area: the mapping does not mirror
  bool groupWithAny = true;                  // no usable derivatives: joins the first group to reach it
  bool degenerate = false;                   // two corners at one position: no edges to group by
  std::array<int, 3> neighbour{-1, -1, -1};  // across the edge from corner c to corner c + 1
  std::array<int, 3> group{-1, -1, -1};      // of corner c
};

MappedTriangle analyseTriangle(const TangentCorner* corner) {
  MappedTriangle triangle;
  const glm::dvec3 d1 = corner[1].position - corner[0].position;
  const glm::dvec3 d2 = corner[2].position - corner[0].position;
  const glm::dvec2 t21 = corner[1].texcoord - corner[0].texcoord;
  const glm::dvec2 t31 = corner[2].texcoord - corner[0].texcoord;
  triangle.degenerate = corner[0].position == corner[1].position || corner[0].position == corner[2].position ||
                        corner[1].position == corner[2].position;
  const double area = t21.x * t31.y - t21.y * t31.x;  // twice the signed texture area
  triangle.orientationPreserving = area > 0.0;
  if (!nonZero(area)) return triangle;
  // dP/du and dP/dv times `area` (Mikkelsen's eqs. 18 and 19). Only their
  // directions are kept, so the sign of `area` is divided out, not its value,
  // which could be small enough to overflow them.
  const glm::dvec3 s = t31.y * d1 - t21.y * d2;
  const glm::dvec3 t = -t31.x * d1 + t21.x * d2;
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const double sLength = robustLength(s);
  const double tLength = robustLength(t);
  if (nonZero(sLength)) triangle.sDirection = (sign / sLength) * s;
  if (nonZero(tLength)) triangle.tDirection = (sign / tLength) * t;
  triangle.groupWithAny = !(nonZero(sLength / std::abs(area)) && nonZero(tLength / std::abs(area)));
  return triangle;
}

// Each corner's vertex, named by the first corner with exactly the same
// position, normal and texture coordinate.
std::vector<int> weld(const std::vector<TangentCorner>& corners) {
  std::map<std::array<double, 8>, int> firstCorner;
  std::vector<int> vertex(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const TangentCorner& c = corners[i];
    const std::array<double, 8> key{c.position.x, c.position.y, c.position.z, c.normal.x,
                                    c.normal.y,   c.normal.z,   c.texcoord.x, c.texcoord.y};
    // NaN would break the map's ordering; exact comparison never welds it.
    if (std::any_of(key.begin(), key.end(), [](double x) { return std::isnan(x); }))
      vertex[i] = int(i);
    else
      vertex[i] = firstCorner.emplace(key, int(i)).first->second;
  }
  return vertex;
}

int cornerAt(const std::vector<int>& vertex, int triangle, int v) {
  for (int c = 0; c < 3; ++c)
    if (vertex[std::size_t(3 * triangle + c)] == v) return c;
  return -1;
}

// Pairs each edge with the first triangle, in triangle order, that runs
// along it the other way and is not yet paired there; an edge shared by more
// than two triangles so pairs them two by two.
void linkNeighbours(const std::vector<int>& vertex, std::vector<MappedTriangle>& triangles) {
  struct Edge {
    int lo, hi, triangle, side;
  };
  std::vector<Edge> edges;
  for (int t = 0; t < int(triangles.size()); ++t) {
    if (triangles[std::size_t(t)].degenerate) continue;
    for (int side = 0; side < 3; ++side) {
      const int a = vertex[std::size_t(3 * t + side)];
      const int b = vertex[std::size_t(3 * t + (side + 1) % 3)];
      edges.push_back({std::min(a, b), std::max(a, b), t, side});
    }
  }
  // Stable: the triangles along one edge stay in triangle order.
  std::stable_sort(edges.begin(), edges.end(),
                   [](const Edge& x, const Edge& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
  const auto start = [&](const Edge& e) { return vertex[std::size_t(3 * e.triangle + e.side)]; };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    if (triangles[std::size_t(e.triangle)].neighbour[std::size_t(e.side)] != -1) continue;
    for (std::size_t j = i + 1; j < edges.size() && edges[j].lo == e.lo && edges[j].hi == e.hi; ++j) {
      const Edge& f = edges[j];
      if (start(f) == start(e) || triangles[std::size_t(f.triangle)].neighbour[std::size_t(f.side)] != -1) continue;
      triangles[std::size_t(e.triangle)].neighbour[std::size_t(e.side)] = f.triangle;
      triangles[std::size_t(f.triangle)].neighbour[std::size_t(f.side)] = e.triangle;
      break;
    }
  }
}

// The corners around one vertex that share a tangent frame: connected across
// edges through the vertex, all mirrored or all not.
struct CornerGroup {
  int vertex;
  bool orientationPreserving;
  std::vector<int> triangles;
};

// Depth first from `seed`, exploring the edge that leaves the vertex before
// the one that enters it. Which triangles join does not depend on that
// order: a triangle holds the vertex at one corner only.
void growGroup(int g, int seed, std::vector<CornerGroup>& groups, std::vector<MappedTriangle>& triangles,
               const std::vector<int>& vertex) {
  CornerGroup& group = groups[std::size_t(g)];
  std::vector<int> pending;
  const auto pushSides = [&](int t, int corner) {
    const MappedTriangle& triangle = triangles[std::size_t(t)];
    pending.push_back(triangle.neighbour[std::size_t((corner + 2) % 3)]);
    pending.push_back(triangle.neighbour[std::size_t(corner)]);
  };
  pushSides(seed, cornerAt(vertex, seed, group.vertex));
  while (!pending.empty()) {
    const int t = pending.back();
    pending.pop_back();
    if (t < 0) continue;
    const int corner = cornerAt(vertex, t, group.vertex);
    MappedTriangle& triangle = triangles[std::size_t(t)];
    if (corner < 0 || triangle.group[std::size_t(corner)] != -1) continue;
    // The one order dependence of the algorithm, as in the reference: a
    // triangle without derivatives takes the orientation of the first group
    // that reaches any of its corners.
    if (triangle.groupWithAny && triangle.group == std::array<int, 3>{-1, -1, -1})
      triangle.orientationPreserving = group.orientationPreserving;
    if (triangle.orientationPreserving != group.orientationPreserving) continue;
    triangle.group[std::size_t(corner)] = g;
    group.triangles.push_back(t);
    pushSides(t, corner);
  }
}

std::vector<CornerGroup> buildGroups(const std::vector<int>& vertex, std::vector<MappedTriangle>& triangles) {
  std::vector<CornerGroup> groups;
  for (int t = 0; t < int(triangles.size()); ++t) {
    if (triangles[std::size_t(t)].degenerate || triangles[std::size_t(t)].groupWithAny) continue;
    for (int c = 0; c < 3; ++c) {
      if (triangles[std::size_t(t)].group[std::size_t(c)] != -1) continue;
      const int g = int(groups.size());
      groups.push_back({vertex[std::size_t(3 * t + c)], triangles[std::size_t(t)].orientationPreserving, {t}});
      triangles[std::size_t(t)].group[std::size_t(c)] = g;
      growGroup(g, t, groups, triangles, vertex);
    }
  }
  return groups;
}

// A group's triangle seen from the group's vertex: its derivatives projected
// into the tangent plane there.
struct GroupMember {
  int triangle;
  glm::dvec3 s, t;
  bool groupWithAny;
};

bool sharesFrame(const GroupMember& a, const GroupMember& b) {
  if (a.triangle == b.triangle || a.groupWithAny || b.groupWithAny) return true;
  return glm::dot(a.s, b.s) > kSplitCosine && glm::dot(a.t, b.t) > kSplitCosine;
}

// The members whose direction (s or t) may point exactly opposite a given
// one's, the only way two members of a group part (kSplitCosine): unit
// directions whose dot product rounds to -1 differ from each other's
// negation by under 1e-7 in each coordinate, so they lie in the cell of the
// negation, or next to it, on a grid of that spacing.
class OppositeDirections {
 public:
  OppositeDirections(const std::vector<GroupMember>& members, glm::dvec3 GroupMember::*direction)
      : direction_(direction) {
    for (std::size_t m = 0; m < members.size(); ++m) cells_[cell(members[m].*direction)].push_back(int(m));
  }

  // Candidates, a superset of the members opposite `member`'s direction.
  std::vector<int> near(const GroupMember& member) const {
    std::vector<int> found;
    const std::array<long long, 3> centre = cell(-(member.*direction_));
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto hit = cells_.find({centre[0] + dx, centre[1] + dy, centre[2] + dz});
          if (hit != cells_.end()) found.insert(found.end(), hit->second.begin(), hit->second.end());
        }
    return found;
  }

 private:
  static std::array<long long, 3> cell(const glm::dvec3& d) {
    return {std::llround(d.x * 1e7), std::llround(d.y * 1e7), std::llround(d.z * 1e7)};
  }
  glm::dvec3 GroupMember::*direction_;
  std::map<std::array<long long, 3>, std::vector<int>> cells_;
};

// The angle of `triangle` at `corner`, measured in the tangent plane.
double cornerAngle(const std::vector<TangentCorner>& corners, int triangle, int corner, const glm::dvec3& normal) {
  const glm::dvec3 at = corners[std::size_t(3 * triangle + corner)].position;
  const glm::dvec3 previous = corners[std::size_t(3 * triangle + (corner + 2) % 3)].position;
  const glm::dvec3 next = corners[std::size_t(3 * triangle + (corner + 1) % 3)].position;
  const double cosine = glm::dot(inPlaneOf(normal, previous - at), inPlaneOf(normal, next - at));
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// Angle weighted, so that the result does not depend on how finely the
// surface around the vertex is cut into triangles.
glm::dvec3 subgroupTangent(const std::vector<const GroupMember*>& subgroup, const CornerGroup& group,
                           const glm::dvec3& normal, const std::vector<TangentCorner>& corners,
                           const std::vector<int>& vertex) {
  glm::dvec3 sum(0.0);
  for (const GroupMember* m : subgroup) {
    if (m->groupWithAny) continue;
    sum += cornerAngle(corners, m->triangle, cornerAt(vertex, m->triangle, group.vertex), normal) * m->s;
  }
  return nonZero(sum) ? unitOrAsIs(sum) : fallbackTangent(normal);
}

void writeGroupTangents(const CornerGroup& group, const std::vector<TangentCorner>& corners,
                        const std::vector<int>& vertex, const std::vector<MappedTriangle>& triangles,
                        std::vector<glm::dvec4>& tangents) {
  const glm::dvec3 normal = corners[std::size_t(group.vertex)].normal;
  std::vector<GroupMember> members;
  for (int t : group.triangles) {
    const MappedTriangle& triangle = triangles[std::size_t(t)];
    members.push_back(
        {t, inPlaneOf(normal, triangle.sDirection), inPlaneOf(normal, triangle.tDirection), triangle.groupWithAny});
  }
  // Sorted, so that a subgroup's member list names it whatever order the
  // group grew in, and its sum is taken in one fixed order.
  std::sort(members.begin(), members.end(),
            [](const GroupMember& a, const GroupMember& b) { return a.triangle < b.triangle; });
  // Corners whose subgroups hold the same triangles share one result, so
  // welded corners get bit-identical tangents. A subgroup is named by the
  // members it leaves out, which are few: most vertices have none.
  std::map<std::vector<int>, glm::dvec3> tangentOfSubgroup;
  const double handedness = group.orientationPreserving ? 1.0 : -1.0;
  const OppositeDirections oppositeS(members, &GroupMember::s), oppositeT(members, &GroupMember::t);
  for (std::size_t m = 0; m < members.size(); ++m) {
    const GroupMember& member = members[m];
    std::vector<int> leftOut;
    for (const OppositeDirections* opposite : {&oppositeS, &oppositeT})
      for (const int other : opposite->near(member))
        if (!sharesFrame(member, members[std::size_t(other)])) leftOut.push_back(other);
    std::sort(leftOut.begin(), leftOut.end());
    leftOut.erase(std::unique(leftOut.begin(), leftOut.end()), leftOut.end());
    auto found = tangentOfSubgroup.find(leftOut);
    if (found == tangentOfSubgroup.end()) {
      std::vector<const GroupMember*> subgroup;
      for (std::size_t other = 0, skip = 0; other < members.size(); ++other) {
        if (skip < leftOut.size() && leftOut[skip] == int(other)) {
          ++skip;
          continue;
        }
        subgroup.push_back(&members[other]);
      }
      found = tangentOfSubgroup.emplace(leftOut, subgroupTangent(subgroup, group, normal, corners, vertex)).first;
    }
    const int corner = cornerAt(vertex, member.triangle, group.vertex);
    tangents[std::size_t(3 * member.triangle + corner)] = glm::dvec4(found->second, handedness);
  }
}

// A triangle with two corners at one position takes, at each corner, what
// the first other triangle's corner at the same vertex got.
void shareWithDegenerate(const std::vector<int>& vertex, const std::vector<MappedTriangle>& triangles,
                         std::vector<glm::dvec4>& tangents) {
  std::map<int, std::size_t> firstSoundCorner;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (!triangles[t].degenerate)
      for (std::size_t c = 0; c < 3; ++c) firstSoundCorner.emplace(vertex[3 * t + c], 3 * t + c);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (triangles[t].degenerate)
      for (std::size_t c = 0; c < 3; ++c) {
        const auto found = firstSoundCorner.find(vertex[3 * t + c]);
        if (found != firstSoundCorner.end()) tangents[3 * t + c] = tangents[found->second];
      }
}

}  // namespace

std::vector<glm::dvec4> mikktspaceTangents(const std::vector<TangentCorner>& corners) {
  if (corners.size() % 3 != 0)
    throw std::invalid_argument("mikktspaceTangents: corners come three per triangle, got " +
                                std::to_string(corners.size()));
  std::vector<glm::dvec4> tangents;
  tangents.reserve(corners.size());
  for (const TangentCorner& c : corners) tangents.emplace_back(fallbackTangent(c.normal), 1.0);
  const std::vector<int> vertex = weld(corners);
  std::vector<MappedTriangle> triangles;
  triangles.reserve(corners.size() / 3);
  for (std::size_t t = 0; t < corners.size() / 3; ++t) triangles.push_back(analyseTriangle(&corners[3 * t]));
  linkNeighbours(vertex, triangles);
  for (const CornerGroup& group : buildGroups(vertex, triangles))
    writeGroupTangents(group, corners, vertex, triangles, tangents);
  shareWithDegenerate(vertex, triangles, tangents);
  return tangents;
}

}  // namespace facet::scene

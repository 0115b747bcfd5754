#include "scenes/camera_medium.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "materials/material.h"

namespace facet::scene {
namespace {

// Limit points per patch edge of the tessellation the crossings are counted
// on: a point closer to the surface than its chordal error may be placed on
// the wrong side, which for an eye means a camera within that of the glass.
constexpr int kSamplesPerPatchEdge = 16;

// The rays the crossings are counted along, off every axis and diagonal so
// that none meets an edge of a tessellation of an axis-aligned cage. Where
// patches of different depths meet, their grids leave slivers between them
// that a ray may slip through; the majority of three rays decides.
const std::array<glm::dvec3, 3> kDirections = {glm::normalize(glm::dvec3(0.2371, 0.9132, 0.3317)),
                                               glm::normalize(glm::dvec3(-0.8123, 0.1975, 0.5489)),
                                               glm::normalize(glm::dvec3(0.4417, -0.3706, -0.8163))};

bool rayMeetsBox(const glm::dvec3& origin, const glm::dvec3& inverse, const Aabb& box) {
  double near = 0.0, far = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    double t0 = (box.lo[axis] - origin[axis]) * inverse[axis], t1 = (box.hi[axis] - origin[axis]) * inverse[axis];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far;
}

// The distance along the ray to triangle (a, b, c), if it meets it ahead
// (Möller and Trumbore 1997).
double triangleDistance(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a, const glm::dvec3& b,
                        const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  constexpr double kNone = -1.0;
  if (det == 0.0) return kNone;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return kNone;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return kNone;
  return glm::dot(e2, q) / det;
}

struct Crossings {
  int count = 0;
  double nearest = std::numeric_limits<double>::infinity();
};

void crossPatch(const BezierPatch& patch, const glm::dvec3& origin, const glm::dvec3& direction, Crossings& crossings) {
  constexpr int n = kSamplesPerPatchEdge;
  std::array<glm::dvec3, (n + 1) * (n + 1)> grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      grid[std::size_t(j * (n + 1) + i)] = evaluateBezierPatch(patch, double(i) / n, double(j) / n).position;
  auto at = [&](int i, int j) { return grid[std::size_t(j * (n + 1) + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (double t : {triangleDistance(origin, direction, at(i, j), at(i + 1, j), at(i + 1, j + 1)),
                       triangleDistance(origin, direction, at(i, j), at(i + 1, j + 1), at(i, j + 1))})
        if (t > 0.0) {
          ++crossings.count;
          crossings.nearest = std::min(crossings.nearest, t);
        }
}

Crossings countCrossings(const ObjectGeometry& object, const glm::dvec3& origin, const glm::dvec3& direction) {
  Crossings crossings;
  const glm::dvec3 inverse = 1.0 / direction;
  const std::vector<PatchBvh::Node>& nodes = object.bvh.nodes();
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int index = stack.back();
    stack.pop_back();
    const PatchBvh::Node& node = nodes[std::size_t(index)];
    if (!rayMeetsBox(origin, inverse, node.bounds)) continue;
    if (!node.leaf()) {
      stack.push_back(index + 1);
      stack.push_back(node.next);
      continue;
    }
    for (int slot = node.next; slot < node.next + node.patchCount; ++slot)
      crossPatch(object.surface.bezierPatch(object.bvh.leafPatches()[std::size_t(slot)]), origin, direction, crossings);
  }
  return crossings;
}

glm::dvec3 solidAbsorption(const materials::Material& material) {
  if (!materials::isTransmissive(material) || material.thinWalled) return glm::dvec3(0.0);
  return materials::transmissionParams64(material).sigma;
}

}  // namespace

int absorbingSolidAround(const Scene& scene, const SceneGeometry& geometry, const glm::dvec3& point) {
  int innermost = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const glm::dvec3 sigma = solidAbsorption(scene.materials[std::size_t(scene.objects[i].material)]);
    if (sigma == glm::dvec3(0.0) || !geometry.objects[i].enclosesSolid || hasCutout(scene.objects[i])) continue;
    int inside = 0;
    double wall = std::numeric_limits<double>::infinity();  // the nearest crossing of a ray that finds it inside
    for (const glm::dvec3& direction : kDirections) {
      const Crossings crossings = countCrossings(geometry.objects[i], point, direction);
      if (crossings.count % 2 == 0) continue;
      ++inside;
      wall = std::min(wall, crossings.nearest);
    }
    if (2 * inside > int(kDirections.size()) && wall < nearest) {
      innermost = int(i);
      nearest = wall;
    }
  }
  return innermost;
}

CameraMedium cameraMedium(const Scene& scene, const SceneGeometry& geometry) {
  CameraMedium medium;
  medium.object = absorbingSolidAround(scene, geometry, scene.camera.eye);
  if (medium.object >= 0)
    medium.sigma = solidAbsorption(scene.materials[std::size_t(scene.objects[std::size_t(medium.object)].material)]);
  return medium;
}

}  // namespace facet::scene

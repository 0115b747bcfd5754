#include "scenes/camera_medium.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "materials/material.h"
#include "scenes/ray_tests.h"

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
  const rules::f64::RayShear shear = rules::f64::ray_shear(direction);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (const auto& [b, c] :
           {std::pair(at(i + 1, j), at(i + 1, j + 1)), std::pair(at(i + 1, j + 1), at(i, j + 1))}) {
        double t = 0.0, wb = 0.0, wc = 0.0;
        if (!rayHitsTriangle(shear, origin, at(i, j), b, c, t, wb, wc) || !(t > 0.0)) continue;
        ++crossings.count;
        crossings.nearest = std::min(crossings.nearest, t);
      }
}

Crossings countCrossings(const ObjectGeometry& object, const glm::dvec3& origin, const glm::dvec3& direction) {
  Crossings crossings;
  const std::vector<PatchBvh::Node>& nodes = object.bvh.nodes();
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int index = stack.back();
    stack.pop_back();
    const PatchBvh::Node& node = nodes[std::size_t(index)];
    if (!rayHitsBox(origin, direction, node.bounds, 0.0, std::numeric_limits<double>::infinity())) continue;
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

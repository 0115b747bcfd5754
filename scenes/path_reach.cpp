#include "scenes/path_reach.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "materials/material.h"

namespace facet::scene {
namespace {

// The limit points of every patch on an (n + 1)^2 grid, with their outward
// unit normals (zero where the derivatives give none).
struct SurfaceSamples {
  std::vector<glm::dvec3> positions, normals;
  int perPatch = 0;
};

SurfaceSamples takeSamples(const SubdivisionSurface& surface) {
  // A bilinear patch (polygons as authored) needs its corners only: n . P is
  // bilinear in (u, v), so its largest value over the patch is at a corner,
  // and a twisted patch is a saddle: the plane at one of two opposite
  // corners leaves the other above it.
  const int n = surface.statistics().subdivision == Subdivision::None ? 1 : kConvexitySamplesPerPatchEdge;
  SurfaceSamples s;
  s.perPatch = (n + 1) * (n + 1);
  for (int p = 0; p < surface.patchCount(); ++p) {
    const PatchDomain& d = surface.patch(p).domain;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const LimitPoint point = surface.evaluatePatch(p, d.u0 + d.size * i / n, d.v0 + d.size * j / n);
        const glm::dvec3 normal = glm::cross(point.du, point.dv);
        const double length = glm::length(normal);
        s.positions.push_back(point.position);
        // A degenerate corner (a pole, a collapsed edge) has no tangent plane of its own to check.
        s.normals.push_back(length > 1e-10 * glm::length(point.du) * glm::length(point.dv) ? normal / length
                                                                                           : glm::dvec3(0.0));
      }
  }
  // OpenSubdiv's normal follows the faces' winding; outward is where the
  // samples lie ahead of their centroid.
  const glm::dvec3 centroid =
      std::accumulate(s.positions.begin(), s.positions.end(), glm::dvec3(0.0)) / double(s.positions.size());
  double outward = 0;
  for (std::size_t i = 0; i < s.positions.size(); ++i) outward += glm::dot(s.normals[i], s.positions[i] - centroid);
  if (outward < 0)
    for (glm::dvec3& normal : s.normals) normal = -normal;
  return s;
}

// The largest n . (y - x) over the samples y of every patch whose box may
// rise more than `floor` above the plane through x, and at least `floor`.
double heightAbovePlane(const SurfaceSamples& s, const PatchBvh& bvh, const glm::dvec3& x, const glm::dvec3& n,
                        double floor) {
  const std::vector<PatchBvh::Node>& nodes = bvh.nodes();
  const double base = glm::dot(n, x);
  double highest = floor;
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const int index = stack.back();
    stack.pop_back();
    const PatchBvh::Node& node = nodes[std::size_t(index)];
    const glm::dvec3 half = 0.5 * (node.bounds.hi - node.bounds.lo);
    if (glm::dot(n, node.bounds.centre()) + glm::dot(glm::abs(n), half) - base <= highest) continue;
    if (!node.leaf()) {
      stack.push_back(node.next);
      stack.push_back(index + 1);
      continue;
    }
    for (int slot = node.next; slot < node.next + node.patchCount; ++slot) {
      const std::size_t first = std::size_t(bvh.leafPatches()[std::size_t(slot)]) * std::size_t(s.perPatch);
      for (std::size_t j = first; j < first + std::size_t(s.perPatch); ++j)
        highest = std::max(highest, glm::dot(n, s.positions[j]) - base);
    }
  }
  return highest;
}

}  // namespace

ConvexityCheck checkConvexity(const SubdivisionSurface& surface, const PatchBvh& bvh, const glm::dvec3& eye,
                              double stopAbove) {
  const SurfaceSamples s = takeSamples(surface);
  const double diagonal = surface.bounds().diagonal();
  ConvexityCheck check;
  check.samples = s.positions.size();
  check.eyeClearance = -std::numeric_limits<double>::infinity();
  double excess = 0;  // every sample lies on its own plane
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    if (s.normals[i] == glm::dvec3(0.0)) continue;
    check.eyeClearance = std::max(check.eyeClearance, glm::dot(s.normals[i], eye - s.positions[i]) / diagonal);
    excess = heightAbovePlane(s, bvh, s.positions[i], s.normals[i], excess);
    if (excess / diagonal > stopAbove) break;
  }
  check.excess = excess / diagonal;
  return check;
}

PathReach pathReach(const Scene& scene, const SceneGeometry& geometry) {
  if (scene.objects.empty()) return {false, "the scene has no object"};
  if (scene.objects.size() > 1) return {true, std::to_string(scene.objects.size()) + " objects can see each other"};
  const Object& object = scene.objects.front();
  const materials::Material& material = scene.materials.at(std::size_t(object.material));
  if (materials::isTransmissive(material)) return {true, "'" + material.name + "' transmits"};
  // The tessellation's own dents (a grid's diagonals, the fans at level
  // transitions) are not checked: it traces.
  if (scene.render.method != IntersectionMethod::Exact) return {true, "the tessellation is not checked for convexity"};
  if (!closesIntoSphere(object.cage)) return {true, "'" + object.name + "' has holes, handles or open edges"};
  const ObjectGeometry& g = geometry.objects.front();
  const ConvexityCheck check = checkConvexity(g.surface, g.bvh, scene.camera.eye, kConvexTolerance);
  if (check.excess > kConvexTolerance) return {true, "'" + object.name + "' is concave"};
  if (check.eyeClearance <= kConvexTolerance) return {true, "the eye is inside '" + object.name + "'"};
  return {false, "one convex closed object, seen from outside; no continuation can hit"};
}

}  // namespace facet::scene

#include "scenes/scene_geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace facet::scene {
namespace {

double meanEdgeLength(const ControlCage& cage) {
  double total = 0;
  std::size_t edges = 0, first = 0;
  for (int count : cage.faceVertexCounts) {
    for (int i = 0; i < count; ++i) {
      const glm::dvec3& a = cage.positions[std::size_t(cage.faceVertexIndices[first + std::size_t(i)])];
      const glm::dvec3& b = cage.positions[std::size_t(cage.faceVertexIndices[first + std::size_t((i + 1) % count)])];
      total += glm::distance(a, b);
      ++edges;
    }
    first += std::size_t(count);
  }
  return edges ? total / double(edges) : 0.0;
}

double distanceToBox(const glm::dvec3& p, const Aabb& box) {
  const glm::dvec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), glm::dvec3(0.0));
  return glm::length(outside);
}

}  // namespace

RefinementChoice chooseRefinement(const Object& object, const Camera& camera, const RenderSettings& settings) {
  Aabb bounds;
  for (const glm::dvec3& p : object.cage.positions) bounds.extend(p);
  // An eye inside the bounds sees the object from as close as it gets; a
  // small floor keeps the projection finite.
  const double distance = std::max(distanceToBox(camera.eye, bounds), 1e-3 * std::max(bounds.diagonal(), 1e-12));
  const double pixelsPerUnit =
      settings.height / (2.0 * std::tan(0.5 * camera.verticalFovDegrees * std::numbers::pi / 180.0) * distance);
  RefinementChoice choice;
  choice.edgePixels = meanEdgeLength(object.cage) * pixelsPerUnit;
  const double ratio = std::max(choice.edgePixels / settings.pixelTolerance, 1.0);
  choice.isolationLevel = object.isolationLevel.value_or(std::clamp(int(std::ceil(0.5 * std::log2(ratio))), 1, 8));
  choice.tessellationRate =
      settings.tessellationRate.value_or(std::clamp(int(std::ceil(std::sqrt(ratio / 8.0))), 1, 64));
  return choice;
}

int SceneGeometry::patchCount() const {
  int count = 0;
  for (const ObjectGeometry& o : objects) count += o.surface.patchCount();
  return count;
}

std::size_t SceneGeometry::bytes() const {
  std::size_t total = 0;
  for (const ObjectGeometry& o : objects) total += o.surface.statistics().openSubdivBytes + o.bvh.statistics().bytes;
  return total;
}

SceneGeometry buildGeometry(const Scene& scene) {
  SceneGeometry geometry;
  for (const Object& object : scene.objects) {
    RefinementChoice choice = chooseRefinement(object, scene.camera, scene.render);
    RefinementSettings settings;
    settings.isolationLevel = choice.isolationLevel;
    settings.endCaps = object.endCaps;
    SubdivisionSurface surface = SubdivisionSurface::create(object.cage, settings);
    PatchBvh bvh = PatchBvh::build(surface);
    geometry.bounds.extend(surface.bounds());
    geometry.objects.push_back({choice, std::move(surface), std::move(bvh)});
  }
  return geometry;
}

std::string describe(const Scene& scene, const SceneGeometry& geometry) {
  std::ostringstream out;
  for (std::size_t i = 0; i < geometry.objects.size(); ++i) {
    const ObjectGeometry& o = geometry.objects[i];
    out << scene.objects[i].name << ": edge " << std::lround(o.refinement.edgePixels) << " px, isolation "
        << o.surface.statistics().isolationLevel << ", dicing " << o.refinement.tessellationRate << "; "
        << describe(o.surface.statistics()) << "; " << describe(o.bvh.statistics()) << "\n";
  }
  out << "total: " << geometry.patchCount() << " patches, " << (geometry.bytes() + 1023) / 1024 << " KiB";
  return out.str();
}

}  // namespace facet::scene

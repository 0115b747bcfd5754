#include "scenes/scene_geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>

#include "scenes/cage_topology.h"
#include "scenes/input_error.h"
#include "scenes/memory_budget.h"

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

// |n . (P00 - P10 + P11 - P01)| of the bilinear patch through four points in
// order around it, n its unit normal at the centre (that of its diagonals).
double outOfPlaneTwist(const glm::dvec3& p00, const glm::dvec3& p10, const glm::dvec3& p11, const glm::dvec3& p01) {
  const glm::dvec3 twist = p00 - p10 + p11 - p01;
  const glm::dvec3 normal = glm::cross(p11 - p00, p01 - p10);
  const double length = glm::length(normal);
  return length > 0 ? std::abs(glm::dot(twist, normal)) / length : glm::length(twist);
}

// Over the bilinear patches Subdivision::None makes: a quad is one, any other
// face one per corner, through the corner, its edge midpoints and the centroid.
double largestTwist(const ControlCage& cage) {
  double largest = 0;
  std::size_t first = 0;
  for (int count : cage.faceVertexCounts) {
    auto corner = [&](int i) -> const glm::dvec3& {
      return cage.positions[std::size_t(cage.faceVertexIndices[first + std::size_t((i + count) % count)])];
    };
    if (count == 4) {
      largest = std::max(largest, outOfPlaneTwist(corner(0), corner(1), corner(2), corner(3)));
    } else {
      glm::dvec3 centroid(0.0);
      for (int i = 0; i < count; ++i) centroid += corner(i);
      centroid /= double(count);
      for (int i = 0; i < count; ++i)
        largest = std::max(largest, outOfPlaneTwist(corner(i), 0.5 * (corner(i) + corner(i + 1)), centroid,
                                                    0.5 * (corner(i - 1) + corner(i))));
    }
    first += std::size_t(count);
  }
  return largest;
}

// Refinement and the CPU reference multiply up to three coordinate
// differences (a twist against a cross product, BVH surface areas, Newton
// steps); within this bound every such product stays finite in double.
constexpr double kMaxCoordinate = 1e100;

void checkExtent(const Object& object) {
  for (std::size_t i = 0; i < object.cage.positions.size(); ++i) {
    const glm::dvec3& p = object.cage.positions[i];
    if (std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate && std::abs(p.z) <= kMaxCoordinate) continue;
    std::ostringstream detail;
    detail << "object '" << object.name << "': vertex " << i + 1 << " is at " << p.x << ", " << p.y << ", " << p.z
           << " in world space";
    throw InputError(object.cage.source, 0, "cage coordinates must lie within +-1e100", detail.str());
  }
}

// A lower bound on what refining a cage holds per quad (a face of n != 4
// sides is n quads): measured on a regular grid, where each quad is one
// patch, the peak grew by 1.2 to 2.2 KB a face on either backend, subdivided
// or as authored (BENCHMARKS.md); irregular cages need more.
constexpr std::uint64_t kRefinementBytesPerQuad = 1024;

// Refuses, before any is refined, cages whose quads alone would take more
// than the memory limit: one clear error, not an allocation that fails
// gigabytes into the refinement.
void checkRefinementFitsInMemory(const Scene& scene) {
  const MemoryLimit limit = memoryLimit();
  std::uint64_t quads = 0;
  for (const Object& object : scene.objects) {
    for (int count : object.cage.faceVertexCounts) quads += count == 4 ? 1 : std::uint64_t(count);
    const std::uint64_t needed = quads * kRefinementBytesPerQuad;
    if (needed <= limit.bytes) continue;
    throw InputError(object.cage.source.empty() ? "the scene" : object.cage.source, 0,
                     "the scene's cages must fit in memory once refined",
                     "object '" + object.name + "' brings the scene's cages to " + std::to_string(quads) +
                         " quads, which need at least " + gigabytes(needed) + " of memory to refine and the limit is " +
                         gigabytes(limit.bytes) + " (" + limit.source + "); decimate the mesh");
  }
}

double distanceToBox(const glm::dvec3& p, const Aabb& box) {
  const glm::dvec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), glm::dvec3(0.0));
  return glm::length(outside);
}

}  // namespace

RefinementChoice chooseRefinement(const Object& object, const Camera& camera, const RenderSettings& settings) {
  checkExtent(object);
  Aabb bounds;
  for (const glm::dvec3& p : object.cage.positions) bounds.extend(p);
  // An eye inside the bounds sees the object from as close as it gets; a
  // small floor keeps the projection finite.
  const double distance = std::max(distanceToBox(camera.eye, bounds), 1e-3 * std::max(bounds.diagonal(), 1e-12));
  const double pixelsPerUnit =
      settings.height / (2.0 * std::tan(0.5 * camera.verticalFovDegrees * std::numbers::pi / 180.0) * distance);
  RefinementChoice choice;
  choice.edgePixels = meanEdgeLength(object.cage) * pixelsPerUnit;
  if (object.subdivision == Subdivision::None) {
    choice.twistPixels = largestTwist(object.cage) * pixelsPerUnit;
    choice.isolationLevel = 0;
    choice.tessellationRate = settings.tessellationRate.value_or(
        std::clamp(int(std::ceil(std::sqrt(choice.twistPixels / (4.0 * settings.pixelTolerance)))), 1, 64));
    return choice;
  }
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
  static std::atomic<std::uint64_t> serials{0};
  checkRefinementFitsInMemory(scene);
  SceneGeometry geometry;
  geometry.serial = ++serials;
  for (const Object& object : scene.objects) {
    RefinementChoice choice = chooseRefinement(object, scene.camera, scene.render);
    RefinementSettings settings;
    settings.isolationLevel = choice.isolationLevel;
    settings.endCaps = object.endCaps;
    settings.subdivision = object.subdivision;
    SubdivisionSurface surface = SubdivisionSurface::create(object.cage, settings);
    PatchBvh bvh = PatchBvh::build(surface);
    geometry.bounds.extend(surface.bounds());
    // Only a solid's inside is sealed off (sealsInside); other objects skip the walk of their edges.
    const bool transmits = materials::isTransmissive(scene.materials[std::size_t(object.material)]);
    geometry.objects.push_back({choice, std::move(surface), std::move(bvh), transmits && enclosesSolid(object.cage)});
  }
  return geometry;
}

std::string describe(const Scene& scene, const SceneGeometry& geometry) {
  std::ostringstream out;
  for (std::size_t i = 0; i < geometry.objects.size(); ++i) {
    const ObjectGeometry& o = geometry.objects[i];
    out << scene.objects[i].name << ": edge " << std::lround(o.refinement.edgePixels) << " px, ";
    if (scene.objects[i].subdivision == Subdivision::None)
      out << "twist " << std::lround(o.refinement.twistPixels) << " px";
    else
      out << "isolation " << o.surface.statistics().isolationLevel;
    out << ", dicing " << o.refinement.tessellationRate << "; " << describe(o.surface.statistics()) << "; "
        << describe(o.bvh.statistics()) << "\n";
  }
  out << "total: " << geometry.patchCount() << " patches, " << (geometry.bytes() + 1023) / 1024 << " KiB";
  return out.str();
}

}  // namespace facet::scene

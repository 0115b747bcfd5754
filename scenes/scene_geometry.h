// Model no more than a scene needs: each object is refined and (for the
// tessellated method) diced only as finely as its size on screen asks for.
// The rules are in docs/rendering.md, "Geometry", and for polygons as
// authored, diced by how far they twist out of their plane, in
// docs/scene-format.md, "Subdivision". A scene's per-object `isolation` and
// render `tess_level` override them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/patch_bvh.h"
#include "scenes/subdivision_surface.h"
#include "scenes/scene.h"

namespace facet::scene {

struct RefinementChoice {
  double edgePixels = 0;
  double twistPixels = 0;  // Subdivision::None only
  int isolationLevel = 1;  // 0 under Subdivision::None
  int tessellationRate = 1;
};

RefinementChoice chooseRefinement(const Object& object, const Camera& camera, const RenderSettings& settings);

struct ObjectGeometry {
  RefinementChoice refinement;
  SubdivisionSurface surface;
  PatchBvh bvh;
  // Its cage's (scenes/cage_topology.h), found where its material transmits;
  // false elsewhere.
  bool enclosesSolid = false;
};

// Whether every ray from inside `object` crosses its surface before it
// reaches anything outside: its cage encloses solids and no cut-out lets a
// ray through (a transmissive material culls no back face).
inline bool sealsInside(const Object& object, const ObjectGeometry& geometry) {
  return geometry.enclosesSolid && !hasCutout(object);
}

struct SceneGeometry {
  std::vector<ObjectGeometry> objects;  // parallel to Scene::objects
  Aabb bounds;
  // Unique to one buildGeometry call, and kept when it moves: what a backend
  // made of a geometry serves another with the same serial. 0: not made by
  // buildGeometry, so never taken for another.
  std::uint64_t serial = 0;
  int patchCount() const;
  std::size_t bytes() const;  // OpenSubdiv data + patch BVHs
};

SceneGeometry buildGeometry(const Scene& scene);

// One line per object: refinement, patch counts and memory.
std::string describe(const Scene& scene, const SceneGeometry& geometry);

}  // namespace facet::scene

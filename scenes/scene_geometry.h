// Model no more than a scene needs: each object is refined and (for the
// tessellated method) diced only as finely as its size on screen asks for.
//
//   edgePixels   the object's mean cage edge, projected at the distance of
//                the nearest point of its bounds (the largest it appears)
//   isolation    Gregory end caps deviate from the limit surface by an amount
//                that shrinks about 4x per level (the irregular region halves
//                and the error is second order), so
//                L = ceil(log4(edgePixels / pixelTolerance)), in [1, 8]
//   dicing rate  a k x k grid on a patch of curvature radius ~ its size s
//                deviates by ~ s / (8 k^2), so
//                k = ceil(sqrt(edgePixels / (8 pixelTolerance))), in [1, 64]
// Polygons as authored (Subdivision::None) need no isolation, and their
// bilinear patches curve only as far as they twist out of their plane:
//   twistPixels  the largest |n . (P00 - P10 + P11 - P01)| of the object's
//                bilinear patches (n the unit normal at a patch's centre,
//                that of its diagonals), projected like edgePixels; 0 for
//                triangles and planar quads
//   dicing rate  two triangles per grid cell deviate from the patch by about
//                twist / (4 k^2), so
//                k = ceil(sqrt(twistPixels / (4 pixelTolerance))), in [1, 64]:
//                1 for a flat mesh, which two triangles per patch reproduce
// A scene's per-object `isolation` and render `tess_level` override these.
#pragma once

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
};

struct SceneGeometry {
  std::vector<ObjectGeometry> objects;  // parallel to Scene::objects
  Aabb bounds;
  int patchCount() const;
  std::size_t bytes() const;  // OpenSubdiv data + patch BVHs
};

SceneGeometry buildGeometry(const Scene& scene);

// One line per object: refinement, patch counts and memory.
std::string describe(const Scene& scene, const SceneGeometry& geometry);

}  // namespace facet::scene

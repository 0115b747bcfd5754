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
  int isolationLevel = 1;
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

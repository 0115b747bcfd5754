// Whether a path's continuation can meet any surface of a scene at all
// (docs/rendering.md, "Scenes whose paths cannot continue"). A continuation
// that misses adds nothing, so where none can hit, tracing paths cannot
// change the image: the front-end then renders with 0 bounces on both
// backends (scenes/light_transport.h), and the image is byte-identical to
// `--bounces 0`.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <limits>
#include <string>

#include "scenes/cage_topology.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::scene {

// Limit points per patch edge at which a Catmull-Clark surface's convexity
// is checked: a grid of (n + 1)^2 points over every patch (a bilinear one
// needs its corners only).
inline constexpr int kConvexitySamplesPerPatchEdge = 8;

// How far a sampled surface is from convex, and where an eye stands, both in
// diagonals of the surface's bounding box.
struct ConvexityCheck {
  // The largest height of a sample above the tangent plane of another
  // (outward, OpenSubdiv's limit normal): 0 for the samples of a convex
  // surface; the first value above `stopAbove` when the check stopped early.
  double excess = 0.0;
  // The largest height of the eye above a sample's tangent plane: above
  // the excess, the eye is outside.
  double eyeClearance = 0.0;
  std::size_t samples = 0;
};

ConvexityCheck checkConvexity(const SubdivisionSurface& surface, const PatchBvh& bvh, const glm::dvec3& eye,
                              double stopAbove = std::numeric_limits<double>::infinity());

// The excess, in diagonals, below which a surface counts as convex: a tenth
// of the leaving offset (SHADOW_OFFSET_IN_DIAGONALS of rules/shading/lights.h),
// so that no ray starting that far above a tangent plane can come back down
// to the surface.
inline constexpr double kConvexTolerance = 1e-7;

// Whether a continuation of `scene`'s paths can hit anything, and why, for
// the render report; the check of convexity runs only for one closed object
// cast exactly.
struct PathReach {
  bool continues = true;
  std::string why;
};
PathReach pathReach(const Scene& scene, const SceneGeometry& geometry);

}  // namespace facet::scene

#pragma once
// Ray casting against OpenSubdiv limit surfaces, two families:
//
// Exact: the BVH leads to candidate patches; each patch's (u, v) domain is
// split into quarters, pruning every piece whose Bézier hull box the ray
// misses, until a piece is flat (its control points lie within
// `flatness` x its size of the bilinear patch through its corners). Newton on
// (u, v, t) then solves P(u, v) = o + t d from the piece's centre, with
// SubdivisionSurface::evaluatePatch (OpenSubdiv's EvaluateBasis) giving P
// and its derivatives. Safeguards: (u, v) is clamped to the patch, a
// singular 3x3 system ends the run, at most 40 steps are taken, and a root
// is accepted only when |P - (o + t d)| <= tolerance
// (a root outside the piece it started from is kept too, but does not
// settle the piece). A root inside settles the piece only where the ray is
// steeper to the plane of its corners than the surface over it can be
// (rules/surface/piece_slope.h, as the GPU decides): a flat piece may be a
// twisted one that a ray crosses twice, and Newton may find the farther
// crossing. A piece whose Newton run fails, or that is not settled, is split
// further, down to `minimumPieceSize`, so grazing rays and roots near tMin
// (rays leaving a surface) are still resolved.
//
// Tessellated: each patch is diced into a k x k grid of limit points
// (TessellatedSurface), two triangles per cell along the (0,0)-(1,1)
// diagonal; the ray is tested against the triangles of every candidate
// patch. Where the neighbour across a patch edge is one level deeper
// (OpenSubdiv's transition bits) its k segments cover half of that edge, so
// the edge also gets the limit points at its k half-steps, and each cell
// along it becomes a fan around the mean of its corners: the grids then
// meet vertex to vertex and the tessellation is watertight.
//
// A hit the optional filter refuses (a one-sided object's back face,
// docs/rendering.md "One-sided surfaces") is passed over as if the surface
// were not there, and the search goes on beyond it; for the exact method a
// refused root still settles its piece, as an accepted one does.
//
// Both are pure functions of their arguments (no caches, no globals), so
// many threads may cast rays against one surface at once. A ray whose
// direction is zero or not finite hits nothing.

#include "engine/cpu/ray.h"
#include "scenes/patch_bvh.h"
#include "scenes/subdivision_surface.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace facet::cpu {

struct ExactSettings {
  // Largest distance allowed between the hit point on the surface and the
  // ray; 0 means 1e-9 x the surface's bounding-box diagonal.
  double tolerance = 0.0;
  // The tolerance never goes below this: far from the origin double
  // resolves no finer (the reference renderer's precisionFloor).
  double precisionFloor = 0.0;
  double flatness = 1e-3;
  // Pieces smaller than this are not split further, Newton decides alone;
  // 0 means 1e-6 x the bounding-box diagonal. Splitting finer only
  // separates two roots closer than this, i.e. rays tangent to within
  // ~1e-12 of the diagonal, and costs a lot exactly along tangent rays.
  double minimumPieceSize = 0.0;
  int maxDepth = 30;
};

// 8 ulps of double at the largest coordinate of `bounds`: a hit's residual
// there is a few ulps of its terms however well Newton converges, and the
// default tolerance of 1e-9 diagonals lies below it once the geometry is
// more than about 1e6 diagonals from the origin.
inline double precisionFloor(const scene::Aabb& bounds) {
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    largest = std::max({largest, std::abs(bounds.lo[axis]), std::abs(bounds.hi[axis])});
  return std::ldexp(largest, -49);
}

// Whether a hit counts; empty: every hit does.
using HitFilter = std::function<bool(const Ray& ray, const SurfaceHit& hit)>;

std::optional<SurfaceHit> intersectExact(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                                         const Ray& ray, const ExactSettings& settings = {},
                                         const HitFilter& filter = {});

// Limit points on a k x k grid over every patch.
class TessellatedSurface {
 public:
  static TessellatedSurface dice(const scene::SubdivisionSurface& surface, int rate);
  // What dice() keeps for `patches` patches at `rate`.
  static std::uint64_t bytes(std::uint64_t patches, int rate);

  int rate() const { return rate_; }
  // Grid point (i, j) of a patch, i along u, j along v, 0 <= i, j <= rate.
  const glm::dvec3& vertex(int patch, int i, int j) const {
    return vertices_[(static_cast<size_t>(patch) * (rate_ + 1) + j) * (rate_ + 1) + i];
  }
  // Limit point halfway along segment i of `edge` (OpenSubdiv's edge
  // order: 0 v=0, 1 u=1, 2 v=1, 3 u=0; i counts along increasing u or v).
  // Only edges with their transition bit set have them.
  const glm::dvec3& edgeMidpoint(int patch, int edge, int i) const {
    return edgeMidpoints_[(static_cast<size_t>(patch) * 4 + edge) * rate_ + i];
  }
  // Box of the cells in row j (between grid rows j and j + 1) of a patch.
  const scene::Aabb& rowBounds(int patch, int j) const { return rowBounds_[static_cast<size_t>(patch) * rate_ + j]; }

 private:
  int rate_ = 0;
  std::vector<glm::dvec3> vertices_;
  std::vector<glm::dvec3> edgeMidpoints_;
  std::vector<scene::Aabb> rowBounds_;
};

std::optional<SurfaceHit> intersectTessellated(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                                               const TessellatedSurface& tessellation, const Ray& ray,
                                               const HitFilter& filter = {});

}  // namespace facet::cpu

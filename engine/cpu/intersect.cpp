#include "engine/cpu/intersect.h"

#include "engine/cpu/limit_normal.h"
#include "rules/rules.h"
#include "scenes/ray_tests.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace facet::cpu {

namespace {

using scene::Aabb;
using scene::PatchBvh;
using scene::SubdivisionSurface;

// Visits the patches of every leaf the ray reaches before the closest hit so
// far; `testPatch(patch)` lowers tBest when it finds a closer hit.
template <typename TestPatch>
void traverse(const PatchBvh& bvh, const Ray& ray, double& tBest, TestPatch&& testPatch) {
  const std::vector<PatchBvh::Node>& nodes = bvh.nodes();
  if (nodes.empty()) return;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const PatchBvh::Node& node = nodes[stack.back()];
    stack.pop_back();
    if (!scene::rayHitsBox(ray.origin, ray.direction, node.bounds, ray.tMin, tBest)) continue;
    if (node.leaf()) {
      for (int k = 0; k < node.patchCount; ++k) testPatch(bvh.leafPatches()[node.next + k]);
      continue;
    }
    const int first = static_cast<int>(&node - nodes.data()) + 1;
    stack.push_back(node.next);
    stack.push_back(first);
  }
}

bool usable(const Ray& ray) {
  const double dd = glm::dot(ray.direction, ray.direction);
  return dd > 0.0 && std::isfinite(dd) && std::isfinite(glm::dot(ray.origin, ray.origin));
}

Aabb grown(Aabb box, double margin) {
  box.lo -= glm::dvec3(margin);
  box.hi += glm::dvec3(margin);
  return box;
}

// Solves [a b c] x = r by Cramer's rule; false if the columns are (nearly)
// dependent.
bool solve3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& r, glm::dvec3& x) {
  double det = glm::dot(a, glm::cross(b, c));
  double scale = glm::length(a) * glm::length(b) * glm::length(c);
  if (!(std::abs(det) > 1e-14 * scale)) return false;
  x = glm::dvec3(glm::dot(r, glm::cross(b, c)), glm::dot(a, glm::cross(r, c)), glm::dot(a, glm::cross(b, r))) / det;
  return true;
}

// Whether a ray along `direction` meets the piece's surface at most once
// (rules/surface/piece_slope.h), so that one root settles the piece: a flat
// piece may still be a twisted one, which a ray can cross twice.
bool crossesOnce(const scene::SubPatchHull& hull, const glm::dvec3& direction) {
  const scene::SubPatchHull::CornerPlaneSlab slab = hull.cornerPlaneSlab();
  return slab.planar &&
         rules::f64::steeper_than(direction, slab.normal, rules::f64::piece_slope_bound(slab.thickness, slab.width));
}

struct Piece {
  double s0, s1, t0, t1;  // patch-local domain, [0,1]^2 is the whole patch
  int depth;
};

class ExactPatchIntersector {
 public:
  ExactPatchIntersector(const SubdivisionSurface& surface, const Ray& ray, const ExactSettings& settings,
                        const HitFilter& filter)
      : surface_(surface), ray_(ray), settings_(settings), filter_(filter) {
    const double diagonal = surface.bounds().diagonal();
    tolerance_ = std::max(settings.tolerance > 0.0 ? settings.tolerance : 1e-9 * diagonal, settings.precisionFloor);
    minimumPieceSize_ =
        std::max(tolerance_, settings.minimumPieceSize > 0.0 ? settings.minimumPieceSize : 1e-6 * diagonal);
  }

  // Closest root of the ray with patch `index` in [ray.tMin, tBest).
  void intersect(int index, double& tBest, std::optional<SurfaceHit>& best) {
    const scene::BezierPatch& bezier = surface_.bezierPatch(index);
    std::vector<Piece> stack{{0.0, 1.0, 0.0, 1.0, 0}};
    while (!stack.empty()) {
      const Piece piece = stack.back();
      stack.pop_back();
      scene::SubPatchHull hull = scene::restrictBezierPatch(bezier, piece.s0, piece.s1, piece.t0, piece.t1);
      const Aabb box = hull.bounds();
      // Grown by the tolerance: a root may sit that far off the hull.
      if (!scene::rayHitsBox(ray_.origin, ray_.direction, grown(box, tolerance_), ray_.tMin, tBest)) continue;
      const double extent = box.diagonal();
      const bool flat = hull.flatnessError() <= settings_.flatness * extent;
      const bool splittable = piece.depth < settings_.maxDepth && extent > minimumPieceSize_;
      if (flat || !splittable) {
        const bool rootInside = newton(index, piece, tBest, best);
        if (!splittable || (rootInside && crossesOnce(hull, ray_.direction))) continue;
      }
      const double sm = 0.5 * (piece.s0 + piece.s1), tm = 0.5 * (piece.t0 + piece.t1);
      const int depth = piece.depth + 1;
      stack.push_back({piece.s0, sm, piece.t0, tm, depth});
      stack.push_back({sm, piece.s1, piece.t0, tm, depth});
      stack.push_back({piece.s0, sm, tm, piece.t1, depth});
      stack.push_back({sm, piece.s1, tm, piece.t1, depth});
    }
  }

 private:
  // Newton from the piece centre; any root found in [tMin, tBest) becomes
  // the closest hit. True when the root lies inside the piece, whether or
  // not it was the closest.
  bool newton(int index, const Piece& piece, double& tBest, std::optional<SurfaceHit>& best) const {
    const scene::PatchDomain& domain = surface_.patch(index).domain;
    auto faceU = [&domain](double s) { return domain.u0 + s * domain.size; };
    auto faceV = [&domain](double t) { return domain.v0 + t * domain.size; };
    const double dd = glm::dot(ray_.direction, ray_.direction);

    double s = 0.5 * (piece.s0 + piece.s1), t = 0.5 * (piece.t0 + piece.t1);
    scene::LimitPoint point = surface_.evaluatePatch(index, faceU(s), faceV(t));
    double rayT = glm::dot(point.position - ray_.origin, ray_.direction) / dd;
    // One Newton step from (s, t) on the residual: the clamped parameters,
    // the limit point there and its ray parameter; false where the system
    // is singular.
    auto step = [&](const glm::dvec3& residual, double& s1, double& t1, scene::LimitPoint& p1, double& rayT1) {
      glm::dvec3 delta;
      if (!solve3(point.du * domain.size, point.dv * domain.size, -ray_.direction, residual, delta)) return false;
      s1 = std::clamp(s - delta.x, 0.0, 1.0);
      t1 = std::clamp(t - delta.y, 0.0, 1.0);
      p1 = surface_.evaluatePatch(index, faceU(s1), faceV(t1));
      // Re-projecting keeps t consistent with the clamped (s, t).
      rayT1 = glm::dot(p1.position - ray_.origin, ray_.direction) / dd;
      return true;
    };
    constexpr int kMaxIterations = 40;
    bool converged = false;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      const glm::dvec3 residual = point.position - ray_.at(rayT);
      const double error = glm::length(residual);
      if (error <= tolerance_) {
        converged = true;
        // Past the tolerance, one more step, as the GPU takes (exact_newton.glsl):
        // convergence is quadratic, so the root lands at double's
        // resolution whatever the tolerance; kept only if it is no worse.
        double s1, t1, rayT1;
        scene::LimitPoint p1;
        if (step(residual, s1, t1, p1, rayT1) && glm::length(p1.position - ray_.at(rayT1)) <= error)
          s = s1, t = t1, point = p1, rayT = rayT1;
        break;
      }
      if (!step(residual, s, t, point, rayT)) return false;
    }
    if (!converged) return false;

    if (rayT < ray_.tMin) return false;
    // A root outside the piece is still a root of the patch, so it is
    // kept; but the piece may hold a closer one of its own, so it is
    // not settled. The margin keeps roots on shared edges inside.
    const double margin = 1e-6 * (piece.s1 - piece.s0);
    const bool inside =
        s >= piece.s0 - margin && s <= piece.s1 + margin && t >= piece.t0 - margin && t <= piece.t1 + margin;
    if (rayT >= tBest) return inside;

    SurfaceHit hit;
    hit.t = rayT;
    hit.position = point.position;
    hit.patch = index;
    const scene::PatchInfo& info = surface_.patch(index);
    hit.ptexFace = info.ptexFace;
    hit.coarseFace = info.coarseFace;
    hit.u = faceU(s);
    hit.v = faceV(t);
    hit.geometricNormal = limitNormal(surface_, index, hit.u, hit.v);
    if (filter_ && !filter_(ray_, hit)) return inside;
    hit.shadingNormal = shadingNormal(surface_, index, hit.u, hit.v, hit.geometricNormal);
    tBest = rayT;
    best = hit;
    return inside;
  }

  const SubdivisionSurface& surface_;
  const Ray& ray_;
  const ExactSettings& settings_;
  const HitFilter& filter_;
  double tolerance_ = 0.0;
  double minimumPieceSize_ = 0.0;
};

}  // namespace

std::optional<SurfaceHit> intersectExact(const SubdivisionSurface& surface, const PatchBvh& bvh, const Ray& ray,
                                         const ExactSettings& settings, const HitFilter& filter) {
  if (!usable(ray)) return std::nullopt;
  ExactPatchIntersector patches(surface, ray, settings, filter);
  std::optional<SurfaceHit> best;
  double tBest = ray.tMax;
  traverse(bvh, ray, tBest, [&](int patch) { patches.intersect(patch, tBest, best); });
  return best;
}

namespace {

// Grid steps of the point halfway along segment i of each edge.
glm::dvec2 edgeMidpointStep(int edge, int i, int rate) {
  switch (edge) {
    case 0:
      return {i + 0.5, 0.0};
    case 1:
      return {static_cast<double>(rate), i + 0.5};
    case 2:
      return {i + 0.5, static_cast<double>(rate)};
    default:
      return {0.0, i + 0.5};
  }
}

}  // namespace

std::uint64_t TessellatedSurface::bytes(std::uint64_t patches, int rate) {
  const auto k = std::uint64_t(std::max(1, rate));
  return patches * ((k + 1) * (k + 1) * sizeof(glm::dvec3) + 4 * k * sizeof(glm::dvec3) + k * sizeof(scene::Aabb));
}

TessellatedSurface TessellatedSurface::dice(const SubdivisionSurface& surface, int rate) {
  TessellatedSurface result;
  result.rate_ = std::max(1, rate);
  const int k = result.rate_;
  const size_t patches = static_cast<size_t>(surface.patchCount());
  result.vertices_.reserve(patches * (k + 1) * (k + 1));
  result.edgeMidpoints_.resize(patches * 4 * k);
  result.rowBounds_.resize(patches * k);
  for (int patch = 0; patch < surface.patchCount(); ++patch) {
    const scene::PatchInfo& info = surface.patch(patch);
    auto limitAt = [&](glm::dvec2 step) {
      return surface
          .evaluatePatch(patch, info.domain.u0 + info.domain.size * step.x / k,
                         info.domain.v0 + info.domain.size * step.y / k)
          .position;
    };
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= k; ++i) result.vertices_.push_back(limitAt({i, j}));
    for (int edge = 0; edge < 4; ++edge) {
      if (!((info.transitionMask >> edge) & 1u)) continue;
      for (int i = 0; i < k; ++i)
        result.edgeMidpoints_[(static_cast<size_t>(patch) * 4 + edge) * k + i] = limitAt(edgeMidpointStep(edge, i, k));
    }
    for (int j = 0; j < k; ++j) {
      Aabb& box = result.rowBounds_[static_cast<size_t>(patch) * k + j];
      for (int i = 0; i <= k; ++i) {
        box.extend(result.vertex(patch, i, j));
        box.extend(result.vertex(patch, i, j + 1));
      }
      // Midpoints of split edges belong to the cells along them: those
      // of the u = 0 and u = 1 edges to row j, the others to the
      // first and last rows.
      for (int edge : {1, 3})
        if ((info.transitionMask >> edge) & 1u) box.extend(result.edgeMidpoint(patch, edge, j));
      if (j == 0 && (info.transitionMask & 1u))
        for (int i = 0; i < k; ++i) box.extend(result.edgeMidpoint(patch, 0, i));
      if (j == k - 1 && (info.transitionMask & 4u))
        for (int i = 0; i < k; ++i) box.extend(result.edgeMidpoint(patch, 2, i));
    }
  }
  return result;
}

namespace {

// A micro-geometry vertex: position and where it sits, in grid steps.
struct GridVertex {
  glm::dvec3 position;
  glm::dvec2 step;
};

// The triangles of cell (i, j), wound like dP/du x dP/dv: two along the
// diagonal, or, when the cell touches a transition edge, a fan around the
// mean of its corners through the cell's boundary with the edge midpoints.
int cellTriangles(const TessellatedSurface& tessellation, int patch, unsigned transitionMask, int i, int j,
                  GridVertex (&triangles)[8][3]) {
  const int k = tessellation.rate();
  auto corner = [&](int di, int dj) {
    return GridVertex{tessellation.vertex(patch, i + di, j + dj), {i + di, j + dj}};
  };
  auto split = [&](int edge, bool onEdge) { return onEdge && ((transitionMask >> edge) & 1u); };
  const bool splitEdge[4] = {split(0, j == 0), split(1, i == k - 1), split(2, j == k - 1), split(3, i == 0)};
  if (!splitEdge[0] && !splitEdge[1] && !splitEdge[2] && !splitEdge[3]) {
    triangles[0][0] = corner(0, 0), triangles[0][1] = corner(1, 0), triangles[0][2] = corner(1, 1);
    triangles[1][0] = corner(0, 0), triangles[1][1] = corner(1, 1), triangles[1][2] = corner(0, 1);
    return 2;
  }
  // Counter-clockwise boundary: each corner, then the midpoint of the edge
  // leaving it if that edge is split.
  const GridVertex corners[4] = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
  const int segment[4] = {i, j, i, j};
  GridVertex boundary[8];
  int count = 0;
  for (int edge = 0; edge < 4; ++edge) {
    boundary[count++] = corners[edge];
    if (splitEdge[edge])
      boundary[count++] = {tessellation.edgeMidpoint(patch, edge, segment[edge]),
                           edgeMidpointStep(edge, segment[edge], k)};
  }
  const GridVertex centre{
      0.25 * (corners[0].position + corners[1].position + corners[2].position + corners[3].position),
      {i + 0.5, j + 0.5}};
  for (int n = 0; n < count; ++n) {
    triangles[n][0] = centre;
    triangles[n][1] = boundary[n];
    triangles[n][2] = boundary[(n + 1) % count];
  }
  return count;
}

}  // namespace

std::optional<SurfaceHit> intersectTessellated(const SubdivisionSurface& surface, const PatchBvh& bvh,
                                               const TessellatedSurface& tessellation, const Ray& ray,
                                               const HitFilter& filter) {
  if (!usable(ray)) return std::nullopt;
  std::optional<SurfaceHit> best;
  double tBest = ray.tMax;
  const int k = tessellation.rate();
  const rules::f64::RayShear shear = rules::f64::ray_shear(ray.direction);
  traverse(bvh, ray, tBest, [&](int patch) {
    const scene::PatchInfo& info = surface.patch(patch);
    for (int j = 0; j < k; ++j) {
      if (!scene::rayHitsBox(ray.origin, ray.direction, tessellation.rowBounds(patch, j), ray.tMin, tBest)) continue;
      for (int i = 0; i < k; ++i) {
        GridVertex triangles[8][3];
        const int count = cellTriangles(tessellation, patch, info.transitionMask, i, j, triangles);
        for (int n = 0; n < count; ++n) {
          const GridVertex& a = triangles[n][0];
          const GridVertex& b = triangles[n][1];
          const GridVertex& c = triangles[n][2];
          double t, wb, wc;
          if (!scene::rayHitsTriangle(shear, ray.origin, a.position, b.position, c.position, t, wb, wc) ||
              t < ray.tMin || t >= tBest)
            continue;
          const glm::dvec2 step = (1.0 - wb - wc) * a.step + wb * b.step + wc * c.step;
          SurfaceHit hit;
          hit.t = t;
          hit.position = ray.at(t);
          hit.geometricNormal = glm::normalize(glm::cross(b.position - a.position, c.position - a.position));
          hit.patch = patch;
          hit.ptexFace = info.ptexFace;
          hit.coarseFace = info.coarseFace;
          hit.u = info.domain.u0 + info.domain.size * step.x / k;
          hit.v = info.domain.v0 + info.domain.size * step.y / k;
          if (filter && !filter(ray, hit)) continue;
          tBest = t;
          hit.shadingNormal = shadingNormal(surface, patch, hit.u, hit.v, limitNormal(surface, patch, hit.u, hit.v));
          best = hit;
        }
      }
    }
  });
  return best;
}

}  // namespace facet::cpu

#pragma once
// Every limit-surface patch facet handles, rewritten in one bicubic Bézier
// form. The GPU evaluates and subdivides this form directly, and its convex
// hull bounds the patch, which is what the BVH and the exact intersector rely
// on.
//
// Layout: points[4*j + i] is the control point in column i (along u) and row
// j (along v). A Gregory patch (OpenSubdiv's 20-point Gregory basis) keeps its
// rational interior: each of the four interior slots blends its point with an
// alternate, with weights that depend on (u, v):
//
//   slot 5  (i=1,j=1):  (u * points[5]  + v * alternates[0]) / (u + v)
//   slot 6  (i=2,j=1):  (v * points[6]  + (1-u) * alternates[1]) / ((1-u) + v)
//   slot 10 (i=2,j=2):  ((1-u) * points[10] + (1-v) * alternates[2]) / ((1-u) + (1-v))
//   slot 9  (i=1,j=2):  ((1-v) * points[9]  + u * alternates[3]) / (u + (1-v))
//
// (a zero denominator occurs only at a corner, where the slot's Bernstein
// weight is zero anyway). Both points of a pair are convex-combined, so the
// patch still lies in the convex hull of all 20 points.

#include <glm/vec3.hpp>

#include <array>

namespace facet::scene {

struct Aabb {
  glm::dvec3 lo{1e300};
  glm::dvec3 hi{-1e300};

  void extend(const glm::dvec3& p);
  void extend(const Aabb& other);
  glm::dvec3 centre() const { return 0.5 * (lo + hi); }
  double diagonal() const;
  double surfaceArea() const;  // 0 when empty
  bool empty() const { return lo.x > hi.x; }
};

struct BezierPatch {
  std::array<glm::dvec3, 16> points{};
  std::array<glm::dvec3, 4> alternates{};  // Gregory only
  bool gregory = false;
};

// The 16 control points of a patch with its Gregory interior pinned at (u, v).
std::array<glm::dvec3, 16> bezierPointsAt(const BezierPatch& patch, double u, double v);

struct BezierSample {
  glm::dvec3 position{0.0};
  glm::dvec3 du{0.0};  // true partial derivatives, Gregory blend included
  glm::dvec3 dv{0.0};
};

// Position and derivatives at local (u, v) in [0, 1]^2.
BezierSample evaluateBezierPatch(const BezierPatch& patch, double u, double v);

// Conservative box around the piece of the patch over [u0, u1] x [v0, v1].
// Restricting a Bézier patch to a sub-square keeps all weights non-negative,
// so the hull of the restricted control points encloses the piece. A Gregory
// interior slot is first widened to the box of the blends its rational
// weight takes over the piece: that box shrinks with the piece, so small
// pieces get tight hulls.
struct SubPatchHull {
  std::array<glm::dvec3, 16> lo;
  std::array<glm::dvec3, 16> hi;

  Aabb bounds() const;
  // Largest distance of a control box from the bilinear patch through the
  // four corner points: zero means the piece is a flat bilinear patch.
  double flatnessError() const;

  // The hull in the frame of the plane through the corner points, as the
  // GPU's oriented bounds take it (compute/raycast/common/patch_hull.glsl):
  // the plane's unit normal, the hull's extent along it and the narrower of
  // its extents across it (along s, and across both). `planar` is false where
  // the corners span no plane.
  struct CornerPlaneSlab {
    glm::dvec3 normal{0.0};
    double thickness = 0.0;
    double width = 0.0;
    bool planar = false;
  };
  CornerPlaneSlab cornerPlaneSlab() const;
};
SubPatchHull restrictBezierPatch(const BezierPatch& patch, double u0, double u1, double v0, double v1);

}  // namespace facet::scene

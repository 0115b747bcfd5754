// OpenSubdiv's patches (B-spline, bilinear, Gregory basis) as the Bézier
// patches the rest of the pipeline sees.
#include "scenes/subdivision_internal.h"

#include <array>

namespace facet::scene::detail {
namespace {

// Folds OpenSubdiv's boundary rule into explicit phantom rows and columns
// (the basis adjustment of a boundary patch equals extrapolating the missing
// row as 2*edge - inner), then converts the uniform B-spline to Bézier form.
BezierPatch bezierFromBSpline(const std::array<glm::dvec3, 16>& cvs, unsigned boundaryMask) {
  std::array<glm::dvec3, 16> g = cvs;
  auto at = [&g](int row, int col) -> glm::dvec3& { return g[4 * row + col]; };
  for (int col = 0; col < 4; ++col) {
    if (boundaryMask & 1u) at(0, col) = 2.0 * at(1, col) - at(2, col);
    if (boundaryMask & 4u) at(3, col) = 2.0 * at(2, col) - at(1, col);
  }
  for (int row = 0; row < 4; ++row) {
    if (boundaryMask & 8u) at(row, 0) = 2.0 * at(row, 1) - at(row, 2);
    if (boundaryMask & 2u) at(row, 3) = 2.0 * at(row, 2) - at(row, 1);
  }
  auto toBezier = [](const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3) {
    return std::array<glm::dvec3, 4>{(p0 + 4.0 * p1 + p2) / 6.0, (2.0 * p1 + p2) / 3.0, (p1 + 2.0 * p2) / 3.0,
                                     (p1 + 4.0 * p2 + p3) / 6.0};
  };
  std::array<glm::dvec3, 16> rows{};
  for (int row = 0; row < 4; ++row) {
    auto b = toBezier(at(row, 0), at(row, 1), at(row, 2), at(row, 3));
    for (int col = 0; col < 4; ++col) rows[4 * row + col] = b[col];
  }
  BezierPatch patch;
  for (int col = 0; col < 4; ++col) {
    auto b = toBezier(rows[col], rows[4 + col], rows[8 + col], rows[12 + col]);
    for (int row = 0; row < 4; ++row) patch.points[4 * row + col] = b[row];
  }
  return patch;
}

// The bilinear patch through OpenSubdiv's four QUADS points (counter-clockwise
// from (0, 0)) as the bicubic Bézier patch it equals: P_ij = bilinear(i/3, j/3).
BezierPatch bezierFromBilinear(const std::array<glm::dvec3, 4>& corners) {
  BezierPatch patch;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      patch.points[4 * j + i] = (double((3 - i) * (3 - j)) * corners[0] + double(i * (3 - j)) * corners[1] +
                                 double(i * j) * corners[2] + double((3 - i) * j) * corners[3]) /
                                9.0;
  return patch;
}

// OpenSubdiv's Gregory basis numbers its 20 points per corner (P, E+, E-,
// F+, F-); this is where each lands in the Bézier grid.
BezierPatch bezierFromGregory(const std::array<glm::dvec3, 20>& cvs) {
  static constexpr int kBoundaryPoint[12] = {0, 1, 7, 5, 2, 6, 16, 12, 15, 17, 11, 10};
  static constexpr int kBoundarySlot[12] = {0, 1, 2, 3, 4, 7, 8, 11, 12, 13, 14, 15};
  static constexpr int kInteriorPrimary[4] = {3, 8, 13, 18};
  static constexpr int kInteriorAlternate[4] = {4, 9, 14, 19};
  static constexpr int kInteriorSlot[4] = {5, 6, 10, 9};
  BezierPatch patch;
  patch.gregory = true;
  for (int k = 0; k < 12; ++k) patch.points[kBoundarySlot[k]] = cvs[kBoundaryPoint[k]];
  for (int k = 0; k < 4; ++k) {
    patch.points[kInteriorSlot[k]] = cvs[kInteriorPrimary[k]];
    patch.alternates[k] = cvs[kInteriorAlternate[k]];
  }
  return patch;
}

}  // namespace

BezierPatch bezierFromPatch(Far::PatchDescriptor::Type type, Far::ConstIndexArray cvs,
                            const std::vector<OsdPoint>& points, unsigned boundaryMask) {
  auto gather = [&](auto& array) {
    for (std::size_t k = 0; k < array.size(); ++k) array[k] = points[std::size_t(cvs[int(k)])].p;
    return array;
  };
  if (type == Far::PatchDescriptor::QUADS) {
    std::array<glm::dvec3, 4> corners;
    return bezierFromBilinear(gather(corners));
  }
  if (type == Far::PatchDescriptor::GREGORY_BASIS) {
    std::array<glm::dvec3, 20> basis;
    return bezierFromGregory(gather(basis));
  }
  std::array<glm::dvec3, 16> bspline;
  return bezierFromBSpline(gather(bspline), boundaryMask);
}

}  // namespace facet::scene::detail

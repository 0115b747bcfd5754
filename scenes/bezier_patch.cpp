#include "scenes/bezier_patch.h"

#include "rules/rules.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace facet::scene {

void Aabb::extend(const glm::dvec3& p) {
  lo = glm::min(lo, p);
  hi = glm::max(hi, p);
}

void Aabb::extend(const Aabb& other) {
  lo = glm::min(lo, other.lo);
  hi = glm::max(hi, other.hi);
}

double Aabb::diagonal() const { return empty() ? 0.0 : glm::length(hi - lo); }

double Aabb::surfaceArea() const {
  if (empty()) return 0.0;
  const glm::dvec3 e = hi - lo;
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

namespace {

// Row-major slot of each Gregory interior point, in the order of `alternates`.
constexpr int kInteriorSlots[4] = {5, 6, 10, 9};

// Weight of the primary point of each interior slot; the alternate gets the
// rest. Matches OpenSubdiv's Gregory basis (see the header for the formulas).
std::array<double, 4> primaryWeights(double u, double v) {
  auto ratio = [](double a, double b) { return a + b > 0.0 ? a / (a + b) : 0.5; };
  return {ratio(u, v), ratio(v, 1.0 - u), ratio(1.0 - u, 1.0 - v), ratio(1.0 - v, u)};
}

struct WeightGradient {
  double du, dv;
};

// Gradients of primaryWeights(): each is a / (a + b) with a, b affine in
// (u, v); zero where the weight is 0/0 (a patch corner, where its Bernstein
// factor vanishes too).
std::array<WeightGradient, 4> primaryWeightGradients(double u, double v) {
  auto gradient = [](double a, double b, glm::dvec2 da, glm::dvec2 db) {
    const double sum = a + b;
    if (!(sum > 0.0)) return WeightGradient{0.0, 0.0};
    const glm::dvec2 g = (b * da - a * db) / (sum * sum);
    return WeightGradient{g.x, g.y};
  };
  const glm::dvec2 dU(1.0, 0.0), dV(0.0, 1.0);
  return {gradient(u, v, dU, dV), gradient(v, 1.0 - u, dV, -dU), gradient(1.0 - u, 1.0 - v, -dU, -dV),
          gradient(1.0 - v, u, -dV, dU)};
}

std::array<double, 4> bernsteinDerivative(double t) {
  double s = 1.0 - t;
  return {-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t};
}

std::array<double, 4> bernstein(double t) {
  double s = 1.0 - t;
  return {s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t};
}

// The cubic's control points over [a, b]: the blossom at (a,a,a), (a,a,b),
// (a,b,b), (b,b,b), each a de Casteljau run with non-negative weights.
std::array<glm::dvec3, 4> restrictCubic(const std::array<glm::dvec3, 4>& c, double a, double b) {
  auto blossom = [&c](double x1, double x2, double x3) {
    glm::dvec3 p[3];
    for (int i = 0; i < 3; ++i) p[i] = (1.0 - x1) * c[i] + x1 * c[i + 1];
    for (int i = 0; i < 2; ++i) p[i] = (1.0 - x2) * p[i] + x2 * p[i + 1];
    return (1.0 - x3) * p[0] + x3 * p[1];
  };
  return {blossom(a, a, a), blossom(a, a, b), blossom(a, b, b), blossom(b, b, b)};
}

std::array<glm::dvec3, 16> restrictGrid(const std::array<glm::dvec3, 16>& grid, double u0, double u1, double v0,
                                        double v1) {
  std::array<glm::dvec3, 16> rows{};
  for (int j = 0; j < 4; ++j) {
    auto r = restrictCubic({grid[4 * j], grid[4 * j + 1], grid[4 * j + 2], grid[4 * j + 3]}, u0, u1);
    for (int i = 0; i < 4; ++i) rows[4 * j + i] = r[i];
  }
  std::array<glm::dvec3, 16> result{};
  for (int i = 0; i < 4; ++i) {
    auto c = restrictCubic({rows[i], rows[4 + i], rows[8 + i], rows[12 + i]}, v0, v1);
    for (int j = 0; j < 4; ++j) result[4 * j + i] = c[j];
  }
  return result;
}

}  // namespace

std::array<glm::dvec3, 16> bezierPointsAt(const BezierPatch& patch, double u, double v) {
  std::array<glm::dvec3, 16> points = patch.points;
  if (patch.gregory) {
    std::array<double, 4> w = primaryWeights(u, v);
    for (int k = 0; k < 4; ++k) {
      int slot = kInteriorSlots[k];
      points[slot] = w[k] * patch.points[slot] + (1.0 - w[k]) * patch.alternates[k];
    }
  }
  return points;
}

BezierSample evaluateBezierPatch(const BezierPatch& patch, double u, double v) {
  const std::array<glm::dvec3, 16> points = bezierPointsAt(patch, u, v);
  const std::array<double, 4> bu = bernstein(u), bv = bernstein(v);
  const std::array<double, 4> du = bernsteinDerivative(u), dv = bernsteinDerivative(v);
  BezierSample sample;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const glm::dvec3& p = points[4 * j + i];
      sample.position += bu[i] * bv[j] * p;
      sample.du += du[i] * bv[j] * p;
      sample.dv += bu[i] * dv[j] * p;
    }
  }
  if (patch.gregory) {
    // The interior points move with (u, v): add B * d(blend) for each.
    const std::array<WeightGradient, 4> gradients = primaryWeightGradients(u, v);
    for (int k = 0; k < 4; ++k) {
      const int slot = kInteriorSlots[k];
      const double b = bu[slot % 4] * bv[slot / 4];
      const glm::dvec3 spread = patch.points[slot] - patch.alternates[k];
      sample.du += b * gradients[k].du * spread;
      sample.dv += b * gradients[k].dv * spread;
    }
  }
  return sample;
}

SubPatchHull restrictBezierPatch(const BezierPatch& patch, double u0, double u1, double v0, double v1) {
  std::array<glm::dvec3, 16> lo = patch.points, hi = patch.points;
  if (patch.gregory) {
    // Over the piece, each primary weight is monotone in u and in v, so
    // its range is spanned by the piece's corners; a corner where the
    // weight is 0/0 (the patch corner itself) leaves the full range.
    double wMin[4] = {1.0, 1.0, 1.0, 1.0}, wMax[4] = {0.0, 0.0, 0.0, 0.0};
    for (double u : {u0, u1}) {
      for (double v : {v0, v1}) {
        const bool undefined[4] = {u + v == 0.0, (1.0 - u) + v == 0.0, (1.0 - u) + (1.0 - v) == 0.0,
                                   u + (1.0 - v) == 0.0};
        std::array<double, 4> w = primaryWeights(u, v);
        for (int k = 0; k < 4; ++k) {
          wMin[k] = std::min(wMin[k], undefined[k] ? 0.0 : w[k]);
          wMax[k] = std::max(wMax[k], undefined[k] ? 1.0 : w[k]);
        }
      }
    }
    for (int k = 0; k < 4; ++k) {
      const int slot = kInteriorSlots[k];
      const glm::dvec3 a = wMin[k] * patch.points[slot] + (1.0 - wMin[k]) * patch.alternates[k];
      const glm::dvec3 b = wMax[k] * patch.points[slot] + (1.0 - wMax[k]) * patch.alternates[k];
      lo[slot] = glm::min(a, b);
      hi[slot] = glm::max(a, b);
    }
  }
  SubPatchHull hull{restrictGrid(lo, u0, u1, v0, v1), {}};
  // A regular patch has lo == hi: one restriction serves both.
  hull.hi = patch.gregory ? restrictGrid(hi, u0, u1, v0, v1) : hull.lo;
  return hull;
}

Aabb SubPatchHull::bounds() const {
  Aabb box;
  for (int k = 0; k < 16; ++k) {
    box.extend(lo[k]);
    box.extend(hi[k]);
  }
  return box;
}

namespace {

// The middle of control slot k's box.
glm::dvec3 middle(const SubPatchHull& hull, int k) { return 0.5 * (hull.lo[k] + hull.hi[k]); }

}  // namespace

SubPatchHull::CornerPlaneSlab SubPatchHull::cornerPlaneSlab() const {
  auto mid = [this](int k) { return middle(*this, k); };
  CornerPlaneSlab slab;
  glm::dvec3 u;
  slab.planar = rules::f64::corner_plane(mid(0), mid(3), mid(12), mid(15), slab.normal, u);
  if (!slab.planar) return slab;
  const glm::dvec3 v = glm::cross(slab.normal, u);
  // The extent of the control boxes along an axis: each box spans
  // |axis| . its half size about its centre.
  auto extent = [this](const glm::dvec3& axis) {
    double low = INFINITY, high = -INFINITY;
    for (int k = 0; k < 16; ++k) {
      const double centre = glm::dot(axis, middle(*this, k));
      const double spread = glm::dot(glm::abs(axis), 0.5 * (hi[k] - lo[k]));
      low = std::min(low, centre - spread);
      high = std::max(high, centre + spread);
    }
    return high - low;
  };
  slab.thickness = extent(slab.normal);
  slab.width = std::min(extent(u), extent(v));
  return slab;
}

double SubPatchHull::flatnessError() const {
  auto mid = [this](int k) { return middle(*this, k); };
  glm::dvec3 c00 = mid(0), c30 = mid(3), c03 = mid(12), c33 = mid(15);
  double error = 0.0;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      double s = i / 3.0, t = j / 3.0;
      glm::dvec3 bilinear = (1 - s) * (1 - t) * c00 + s * (1 - t) * c30 + (1 - s) * t * c03 + s * t * c33;
      int k = 4 * j + i;
      error = std::max(error, glm::length(mid(k) - bilinear) + 0.5 * glm::length(hi[k] - lo[k]));
    }
  }
  return error;
}

}  // namespace facet::scene

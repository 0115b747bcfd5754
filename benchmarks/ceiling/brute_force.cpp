#include "benchmarks/ceiling/brute_force.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace facet::benchmarks::ceiling {
namespace {

using glm::dvec3;

// Möller-Trumbore in double over the float vertices: t in (0, tMax), else inf.
double intersect(const Triangle& tri, dvec3 o, dvec3 d, double tMax) {
  const dvec3 v0(tri.a), e1 = dvec3(tri.b) - v0, e2 = dvec3(tri.c) - v0;
  const dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0) return kInf;
  const dvec3 s = o - v0, q = glm::cross(s, e1);
  const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
  return (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < tMax) ? t : kInf;
}

}  // namespace

double bruteForce(const std::vector<Triangle>& tris, dvec3 o, dvec3 d, double tMax, bool anyHit) {
  double best = kInf;
  for (const Triangle& tri : tris) {
    best = std::min(best, intersect(tri, o, d, std::min(best, tMax)));
    if (anyHit && best < kInf) break;
  }
  return best;
}

}  // namespace facet::benchmarks::ceiling

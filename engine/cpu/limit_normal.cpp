#include "engine/cpu/limit_normal.h"

#include <glm/geometric.hpp>

#include <array>

namespace facet::cpu {

namespace {

using real = double;
using vec3 = glm::dvec3;
using glm::length;
#define FACET_FN inline
#include "compute/shared/authored_normal.h"
#undef FACET_FN

bool wellDefined(const scene::LimitPoint& point, glm::dvec3& normal) {
  glm::dvec3 n = glm::cross(point.du, point.dv);
  double scale = glm::length(point.du) * glm::length(point.dv);
  if (!(scale > 0.0) || glm::length(n) <= kDegenerateSine * scale) return false;
  normal = glm::normalize(n);
  return true;
}

}  // namespace

glm::dvec3 limitNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v) {
  glm::dvec3 normal(0.0);
  if (wellDefined(surface.evaluatePatch(patch, u, v), normal)) return normal;

  const scene::PatchDomain& domain = surface.patch(patch).domain;
  const double centreU = domain.u0 + 0.5 * domain.size, centreV = domain.v0 + 0.5 * domain.size;
  for (double step = 1e-7; step <= 1e-3; step *= 10.0) {
    double nu = u + step * (centreU - u), nv = v + step * (centreV - v);
    if (wellDefined(surface.evaluatePatch(patch, nu, nv), normal)) return normal;
  }
  // Degenerate across the whole neighbourhood (a collapsed patch): the
  // normal at the patch centre is the best we know.
  scene::LimitPoint centre = surface.evaluatePatch(patch, centreU, centreV);
  glm::dvec3 fallback = glm::cross(centre.du, centre.dv);
  double length = glm::length(fallback);
  return length > 0.0 ? fallback / length : glm::dvec3(0.0, 0.0, 1.0);
}

glm::dvec3 shadingNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v,
                         const glm::dvec3& limit) {
  const std::array<glm::dvec3, 4>* corners = surface.authoredNormals(patch);
  if (!corners) return limit;
  const scene::PatchDomain& domain = surface.patch(patch).domain;
  const glm::dvec3 n = authored_normal((*corners)[0], (*corners)[1], (*corners)[2], (*corners)[3],
                                       (u - domain.u0) / domain.size, (v - domain.v0) / domain.size);
  if (n == glm::dvec3(0.0)) return limit;
  return glm::dot(n, limit) < 0.0 ? -n : n;
}

}  // namespace facet::cpu

#include "engine/cpu/limit_normal.h"

#include <glm/geometric.hpp>

#include <array>

#include "rules/rules.h"

namespace facet::cpu {

using namespace rules::f64;

glm::dvec3 limitNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v) {
  glm::dvec3 normal(0.0);
  scene::LimitPoint point = surface.evaluatePatch(patch, u, v);
  if (well_defined_normal(point.du, point.dv, normal)) return normal;

  const scene::PatchDomain& domain = surface.patch(patch).domain;
  const double centreU = domain.u0 + 0.5 * domain.size, centreV = domain.v0 + 0.5 * domain.size;
  for (int probe = 0; probe < LIMIT_NORMAL_PROBES; ++probe) {
    const double step = limit_normal_probe_step(probe);
    point = surface.evaluatePatch(patch, toward_patch_centre(u, centreU, step), toward_patch_centre(v, centreV, step));
    if (well_defined_normal(point.du, point.dv, normal)) return normal;
  }
  scene::LimitPoint centre = surface.evaluatePatch(patch, centreU, centreV);
  return unit_normal_or_up(glm::cross(centre.du, centre.dv));
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

glm::dvec4 meshTangent(const scene::SubdivisionSurface& surface, int patch, double u, double v) {
  const std::array<glm::dvec4, 4>* corners = surface.authoredTangents(patch);
  if (!corners) return glm::dvec4(0.0);
  const scene::PatchDomain& domain = surface.patch(patch).domain;
  return mesh_tangent((*corners)[0], (*corners)[1], (*corners)[2], (*corners)[3], (u - domain.u0) / domain.size,
                      (v - domain.v0) / domain.size);
}

}  // namespace facet::cpu

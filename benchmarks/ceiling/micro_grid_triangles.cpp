#include "benchmarks/ceiling/micro_grid_triangles.h"

namespace facet::benchmarks::ceiling {
namespace {

using glm::dvec3;
using glm::vec3;

}  // namespace

std::vector<Triangle> dice(const facet::scene::SceneGeometry& geometry, dvec3 eye) {
  std::vector<Triangle> out;
  std::vector<vec3> grid;
  for (const facet::scene::ObjectGeometry& object : geometry.objects) {
    const int k = object.refinement.tessellationRate;
    for (int patch = 0; patch < object.surface.patchCount(); ++patch) {
      const facet::scene::PatchDomain& domain = object.surface.patch(patch).domain;
      grid.clear();
      for (int j = 0; j <= k; ++j)
        for (int i = 0; i <= k; ++i)
          grid.push_back(
              vec3(object.surface.evaluatePatch(patch, domain.u0 + domain.size * i / k, domain.v0 + domain.size * j / k)
                       .position -
                   eye));
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const vec3 &c00 = grid[j * (k + 1) + i], &c10 = grid[j * (k + 1) + i + 1];
          const vec3 &c01 = grid[(j + 1) * (k + 1) + i], &c11 = grid[(j + 1) * (k + 1) + i + 1];
          out.push_back({c00, c10, c11});
          out.push_back({c00, c11, c01});
        }
    }
  }
  return out;
}

}  // namespace facet::benchmarks::ceiling

#include "engine/cpu/path_tracer.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace facet::cpu {

namespace m = rules::f64;

glm::dvec3 tracePath(const PathScene& scene, const PathVertex& first, const PathSampleKey& key, int bounces,
                     std::vector<BounceRays>& rays) {
  glm::dvec3 radiance = first.radiance;
  glm::dvec3 throughput(1.0);
  PathVertex vertex = first;
  for (int bounce = 1; bounce <= bounces; ++bounce) {
    const auto vertexIndex = std::uint32_t(bounce);
    const double survival = m::path_survival_probability(throughput, vertexIndex);
    if (survival < 1.0) {
      if (m::path_roulette_u(key.pixel, key.sample, key.samples, key.seed, vertexIndex) >= survival) break;
      throughput /= survival;
    }
    const glm::dvec2 u = m::path_continuation_u(key.pixel, key.sample, key.samples, key.seed, vertexIndex);
    const m::PathContinuation next =
        m::continue_path(vertex.params, vertex.n, vertex.ng, vertex.v, vertex.specularScale, u);
    throughput *= next.weight;
    if (throughput == glm::dvec3(0.0)) break;

    BounceRays& counts = rays[std::size_t(bounce)];
    ++counts.rays;
    const double offset = scene.leavingOffset();
    const Ray ray{m::shadow_ray_origin(vertex.position, vertex.ng, offset), next.direction, offset};
    const std::optional<PathVertex> hit = scene.shadeNearest(
        ray, key.pixel, key.sample, m::path_vertex_seed(key.seed, vertexIndex + 1), counts.shadowRays);
    if (!hit) break;  // the environment was counted, shadowed, by D at the vertex the ray left
    ++counts.hits;
    radiance += throughput * hit->radiance;
    vertex = *hit;
  }
  return radiance;
}

}  // namespace facet::cpu

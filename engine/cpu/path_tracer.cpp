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
    const glm::dvec3 l = m::sample_brdf_lobes(vertex.params, vertex.n, vertex.v, u);
    if (!m::above_surface(vertex.n, vertex.ng, l)) break;
    const double pdf = m::brdf_lobes_pdf(vertex.params, vertex.n, l, vertex.v);
    if (!(pdf > 0.0)) break;
    const glm::dvec3 f = m::brdf_evaluate_scaled(vertex.params, vertex.n, l, vertex.v, vertex.specularScale);
    throughput *= f * glm::dot(vertex.n, l) / pdf;
    if (throughput == glm::dvec3(0.0)) break;

    BounceRays& counts = rays[std::size_t(bounce)];
    ++counts.rays;
    const double offset = scene.leavingOffset();
    const Ray ray{m::shadow_ray_origin(vertex.position, vertex.ng, offset), l, offset};
    const std::optional<PathVertex> next = scene.shadeNearest(
        ray, key.pixel, key.sample, m::path_vertex_seed(key.seed, vertexIndex + 1), counts.shadowRays);
    if (!next) break;  // the environment was counted, shadowed, by D at the vertex the ray left
    ++counts.hits;
    radiance += throughput * next->radiance;
    vertex = *next;
  }
  return radiance;
}

}  // namespace facet::cpu

#include "engine/cpu/path_tracer.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace facet::cpu {

namespace m = rules::f64;

glm::dvec3 tracePath(const PathScene& scene, const PathVertex& first, const PathSampleKey& key, int bounces,
                     std::vector<BounceRays>& rays, const LobeLimits& limits) {
  const int limit[3] = {limits.diffuse, limits.glossy, limits.transmission};
  int taken[3] = {0, 0, 0};
  glm::dvec3 radiance = first.radiance;
  glm::dvec3 throughput(1.0);
  PathVertex vertex = first;
  glm::dvec3 sigma(0.0);  // absorption of the medium the path travels in: air, or inside a transmissive object
  for (int bounce = 1; bounce <= bounces; ++bounce) {
    const auto vertexIndex = std::uint32_t(bounce);
    const double survival = m::path_survival_probability(throughput, vertexIndex);
    if (survival < 1.0) {
      if (m::path_roulette_u(key.pixel, key.sample, key.samples, key.seed, vertexIndex) >= survival) break;
      throughput /= survival;
    }
    const glm::dvec2 u = m::path_continuation_u(key.pixel, key.sample, key.samples, key.seed, vertexIndex);
    glm::dvec3 direction;
    bool transmitted = false;
    int lobe = m::PATH_LOBE_DIFFUSE;
    if (vertex.transmissive) {
      const m::TransmissiveContinuation next =
          m::continue_path_transmissive(vertex.params, vertex.transmission, vertex.n, vertex.ng, vertex.v, u,
                                        m::path_interface_u(key.pixel, key.sample, key.samples, key.seed, vertexIndex));
      direction = next.direction;
      transmitted = next.transmitted;
      lobe = next.lobe;
      throughput *= next.weight;
      if (transmitted && !vertex.transmission.thin_walled)
        sigma = vertex.outside ? vertex.transmission.sigma : glm::dvec3(0.0);
    } else {
      const m::PathContinuation next =
          m::continue_path(vertex.params, vertex.n, vertex.ng, vertex.v, vertex.specularScale, u);
      direction = next.direction;
      lobe = m::opaque_continuation_lobe(vertex.params, vertex.n, vertex.v, u);
      throughput *= next.weight;
    }
    if (!m::path_lobe_allowed(taken[lobe], limit[lobe])) break;
    ++taken[lobe];
    if (throughput == glm::dvec3(0.0)) break;

    BounceRays& counts = rays[std::size_t(bounce)];
    ++counts.rays;
    const double offset = scene.leavingOffset();
    const Ray ray{m::shadow_ray_origin(vertex.position, transmitted ? -vertex.ng : vertex.ng, offset), direction,
                  offset};
    const std::optional<PathVertex> hit = scene.shadeNearest(
        ray, key.pixel, key.sample, m::path_vertex_seed(key.seed, vertexIndex + 1), counts.shadowRays);
    const bool absorbing = sigma != glm::dvec3(0.0);
    if (!hit) {
      // D at the vertex the ray left counted the environment, shadowed, over
      // its reflection lobes; its transmission lobe leads here only.
      if (transmitted)
        radiance += throughput * m::beer_lambert(sigma, m::INFINITE_DISTANCE) * scene.escapedRadiance(direction);
      break;
    }
    ++counts.hits;
    if (absorbing) throughput *= m::beer_lambert(sigma, glm::length(hit->position - ray.origin));
    radiance += throughput * hit->radiance;
    vertex = *hit;
  }
  return radiance;
}

}  // namespace facet::cpu

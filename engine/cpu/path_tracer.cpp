#include "engine/cpu/path_tracer.h"

#include <glm/geometric.hpp>

namespace facet::cpu {

namespace m = rules::f64;

glm::dvec3 tracePath(const PathScene& scene, const ShadedVertex& first, const m::PathCarry& start,
                     const m::PathSampleKey& key, int bounces, std::vector<BounceRays>& rays,
                     const LobeLimits& limits) {
  const glm::ivec3 limit(limits.diffuse, limits.glossy, limits.transmission);
  const bool limited = glm::any(glm::greaterThanEqual(limit, glm::ivec3(0)));
  const double offset = scene.leavingOffset();
  glm::dvec3 radiance = start.throughput * first.radiance;
  m::PathCarry carry = start;
  m::PathVertex vertex = first.vertex;
  int hitObject = first.object;
  for (int bounce = 1; bounce <= bounces; ++bounce) {
    const m::PathStep step = m::path_step(vertex, carry, key, std::uint32_t(bounce), limited, limit, offset);
    if (!step.continues) break;
    carry = step.carry;

    BounceRays& counts = rays[std::size_t(bounce)];
    ++counts.rays;
    Ray ray{step.origin, step.direction, step.t_min};
    ray.crossedObject = hitObject;
    ray.crossing = step.crossing;
    const std::optional<ShadedVertex> hit = scene.shadeNearest(
        ray, key.pixel, key.sample_index, m::path_vertex_seed(key.seed, std::uint32_t(bounce) + 1), counts.shadowRays);
    if (!hit) {
      // D at the vertex the ray left counted the environment, shadowed, over
      // its reflection lobes; its transmission lobe leads here only.
      if (step.transmitted)
        radiance += carry.throughput * m::beer_lambert(carry.sigma, m::INFINITE_DISTANCE) *
                    scene.escapedRadiance(step.direction);
      break;
    }
    ++counts.hits;
    carry.throughput *= m::segment_transmittance(carry.sigma, vertex.position, hit->vertex.position);
    radiance += carry.throughput * hit->radiance;
    vertex = hit->vertex;
    hitObject = hit->object;
  }
  return radiance;
}

}  // namespace facet::cpu

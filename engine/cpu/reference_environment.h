// The environment's light at a vertex of the CPU reference, by the scene's
// IBL method (docs/rendering.md, "Image-based light"): what its samples offer
// above the surface, and what of that arrives past their shadow rays, which
// the caller traces.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>

#include "engine/ibl/environment_lighting.h"
#include "rules/rules.h"

namespace facet::cpu {

struct EnvironmentLight {
  glm::dvec3 offered{0.0};
  glm::dvec3 arriving{0.0};
};

// The numbers of a shaded vertex: its camera sample and the seed of its
// environment pairs, which also key its shadow rays (pass_through_key), one
// slot per light and then the environment's.
struct VertexKey {
  std::uint32_t pixel = 0, sample = 0, seed = 0, lights = 0;
  std::uint32_t shadowRay(std::uint32_t slot) const { return rules::f64::pass_through_key(pixel, sample, seed, slot); }
};

// Whether something blocks the shadow ray that leaves the vertex along
// `direction`, whose key is `passThroughKey`.
using ShadowTest = std::function<bool(const glm::dvec3& direction, std::uint32_t passThroughKey)>;

class ReferenceEnvironment {
 public:
  explicit ReferenceEnvironment(const ibl::EnvironmentLighting& lighting) : lighting_(lighting) {}

  // The radiance arriving from world direction `world`.
  glm::dvec3 radiance(const glm::dvec3& world) const;

  // The seed of its samples at a path's first vertex (rules/sampling/path_samples.h).
  std::uint32_t seed() const { return lighting_.environment->seed; }

  // The light at a vertex of BRDF `params` (energy compensation's
  // `specularScale`), of scene material `material`, with normals n and ng
  // facing v.
  EnvironmentLight at(const rules::f64::BrdfParams& params, const glm::dvec3& specularScale, int material,
                      const glm::dvec3& n, const glm::dvec3& ng, const glm::dvec3& v, const VertexKey& key,
                      const ShadowTest& blocked) const;

 private:
  EnvironmentLight sampled(const rules::f64::BrdfParams& params, const glm::dvec3& specularScale, const glm::dvec3& n,
                           const glm::dvec3& ng, const glm::dvec3& v, const VertexKey& key,
                           const ShadowTest& blocked) const;
  EnvironmentLight filtered(const rules::f64::BrdfParams& params, const glm::dvec3& specularScale, const glm::dvec3& n,
                            const glm::dvec3& ng, const glm::dvec3& v, const VertexKey& key,
                            const ShadowTest& blocked) const;
  glm::dvec3 prefiltered(const rules::f64::BrdfParams& params, const glm::dvec3& specularScale, int material,
                         const glm::dvec3& n, const glm::dvec3& v) const;
  glm::dvec3 toMap(const glm::dvec3& world) const;
  glm::dvec3 fromMap(const glm::dvec3& map) const;

  const ibl::EnvironmentLighting& lighting_;
};

}  // namespace facet::cpu

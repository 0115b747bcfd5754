// Paths on the CPU reference (docs/rendering.md, "Paths"): per camera
// sample that hits,
//   L = D(x1) + T1 D(x2) + T1 T2 D(x3) + ...,
// D(x) the per-hit estimator of direct light at x (punctual lights, the
// environment by the scene's IBL method with its shadow rays, emission), and
// each continuation drawn from the whole BRDF at its vertex, T = f |cos| / pdf.
// A continuation that misses adds nothing: D at the vertex it left already
// counted the environment, shadowed. Except through a transmissive material
// ("Transmission and absorption"): D counts its reflection lobes only, so a
// continuation that left through the surface and misses adds the
// environment's radiance, and a segment inside takes Beer-Lambert's factor.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/cpu/ray.h"
#include "rules/rules.h"

namespace facet::cpu {

// A shaded vertex: D(x) towards v, and the vertex its path continues from
// (rules/shading/path_step.h).
struct ShadedVertex {
  glm::dvec3 radiance{0.0};  // D(x)
  rules::f64::PathVertex vertex{};
  int object = -1;  // the scene's object the vertex lies on
};

// The rays of one bounce: bounce 0 is the camera rays and the shadow rays of
// their hits; bounce k >= 1 the continuation rays that leave vertex k and the
// shadow rays of the vertices they hit.
struct BounceRays {
  std::uint64_t rays = 0;  // camera or continuation rays
  std::uint64_t hits = 0;  // of those, the ones that hit a surface
  std::uint64_t shadowRays = 0;
};

// What a path needs of the scene.
class PathScene {
 public:
  // D at the nearest hit of `ray`, seen from the ray's origin, its
  // environment pairs drawn with `seed`; none where the ray hits nothing.
  virtual std::optional<ShadedVertex> shadeNearest(const Ray& ray, std::uint32_t pixel, std::uint32_t sample,
                                                 std::uint32_t seed, std::uint64_t& shadowRays) const = 0;
  // The offset of rays that leave a surface (shadow_ray_offset).
  virtual double leavingOffset() const = 0;
  // The environment's radiance from `direction` (0 without one).
  virtual glm::dvec3 escapedRadiance(const glm::dvec3& direction) const = 0;

 protected:
  ~PathScene() = default;
};

// Continuations of each lobe kind a path may take (PATH_LOBE_*); -1: no limit of its own.
struct LobeLimits {
  int diffuse = -1;
  int glossy = -1;
  int transmission = -1;
};

// L of the path whose first vertex is `first` (shaded with the scene's
// seed), reached as `start` says (camera_path_start), with at most `bounces`
// continuations; `rays` (bounces + 1 entries) counts each bounce's
// continuation and shadow rays.
glm::dvec3 tracePath(const PathScene& scene, const ShadedVertex& first, const rules::f64::PathCarry& start,
                     const rules::f64::PathSampleKey& key, int bounces, std::vector<BounceRays>& rays,
                     const LobeLimits& limits = {});

}  // namespace facet::cpu

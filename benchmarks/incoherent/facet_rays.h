// facet's GPU traversal over a given ray list: the scene packed, diced and
// refitted as GpuRenderer does it (tessellated method), then the path loop's
// own intersect kernel (intersect.comp, PATHS = 1) dispatched indirectly over
// the list as a bounce's continuation rays are, timed by GPU timestamps.
#pragma once

#include <memory>
#include <vector>

#include "benchmarks/incoherent/ray_list.h"
#include "engine/gpu/gpu.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::benchmarks::incoherent {

class FacetRays {
 public:
  FacetRays(gpu::Device& device, const scene::Scene& scene, const scene::SceneGeometry& geometry);
  ~FacetRays();

  // The offset facet's continuation rays leave the surface by
  // (rules' shadow_ray_offset of the scene's diagonal and root tolerance).
  float shadowOffset() const;

  // Uploads the list; trace() and work() then run over it.
  void setRays(const std::vector<Ray>& rays);
  Traced trace();
  // The benchmark's counted copy of the traversal (ceiling/facet_counted.comp).
  Work work();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace facet::benchmarks::incoherent

// The ceiling (benchmarks/ceiling/) over a given ray list: the same
// micro-grids as plain triangles in its BVH4, one ray per invocation
// (ceiling/closest_hit_rays.comp), timed by GPU timestamps.
#pragma once

#include <memory>
#include <vector>

#include "benchmarks/ceiling/triangle_bvh4.h"
#include "benchmarks/incoherent/ray_list.h"
#include "engine/gpu/gpu.h"

namespace facet::benchmarks::incoherent {

class CeilingRays {
 public:
  CeilingRays(gpu::Device& device, const ceiling::Bvh4& bvh);
  ~CeilingRays();

  void setRays(const std::vector<Ray>& rays);
  Traced trace();  // with the triangle hit per ray
  // ceiling/closest_hit_rays_counted.comp: nodes tested, leaves reached, triangles tested.
  Work work();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace facet::benchmarks::incoherent

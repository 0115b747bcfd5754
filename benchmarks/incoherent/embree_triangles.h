// Embree 3 over the ceiling's triangles (the same tessellation, relative to
// the eye): one rtcIntersect1 per ray of a list, on `threads` threads. Only
// built where Embree is found (FACET_HAVE_EMBREE).
#pragma once

#include <memory>
#include <vector>

#include "benchmarks/ceiling/micro_grid_triangles.h"
#include "benchmarks/incoherent/ray_list.h"

namespace facet::benchmarks::incoherent {

class EmbreeTriangles {
 public:
  EmbreeTriangles(const std::vector<ceiling::Triangle>& tris, int threads);
  ~EmbreeTriangles();
  EmbreeTriangles(const EmbreeTriangles&) = delete;
  EmbreeTriangles& operator=(const EmbreeTriangles&) = delete;

  double commitMs() const { return commitMs_; }
  Traced trace(const std::vector<Ray>& rays) const;  // wall clock

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
  int threads_;
  double commitMs_ = 0;
};

}  // namespace facet::benchmarks::incoherent

// Embree 3 as a peer: its subdivision geometry (RTC_GEOMETRY_TYPE_SUBDIVISION)
// built from a facet control cage, tessellated at a chosen rate, casting the
// same camera rays as facet. Used by raycast_bench and `facet bench`; only
// built when Embree is found (target facet_embree_peer, FACET_HAVE_EMBREE).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace facet::peers {

class EmbreeSubdivision {
 public:
  // Edge creases, corner sharpness (>= 10 taken as infinite, as OpenSubdiv
  // does), holes and the boundary mode are carried over; Chaikin creasing
  // has no Embree equivalent (said in notes()).
  EmbreeSubdivision(const scene::ControlCage& cage, int threads);
  ~EmbreeSubdivision();
  EmbreeSubdivision(const EmbreeSubdivision&) = delete;
  EmbreeSubdivision& operator=(const EmbreeSubdivision&) = delete;

  // Segments per cage edge; returns the commit (tessellation + BVH) time in ms.
  double setTessellationRate(int rate);

  // One rtcIntersect1 per pixel centre on the threads given at construction;
  // fills `depth` (distance along the unit ray, +inf on a miss) and returns
  // the time in ms.
  double castPrimary(const scene::Camera& camera, int width, int height, std::vector<float>& depth) const;

  // The same rays and depth image as castPrimary, one rtcIntersect8 per 4×2
  // pixel tile (lanes outside the image masked off).
  double castPrimary8(const scene::Camera& camera, int width, int height, std::vector<float>& depth) const;

  const std::string& notes() const { return notes_; }

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
  int threads_;
  std::string notes_;
};

}  // namespace facet::peers

// raycast_bench --incoherent (issue 24): secondary rays, as facet's path
// loop traces them, against the ceiling kernel and Embree's rtcIntersect1 on
// the very same rays, with the camera rays of the same scene for contrast.
//
// Per scene (a cage framed by sceneFromCage, tessellated method at its own
// dicing rate): the camera rays (one per pixel centre) are cast by the
// ceiling; from each hit, a continuation ray leaves the micro-triangle's
// point, offset along its normal (facing the eye) by facet's own
// shadow_ray_offset, in a cosine-distributed direction about that normal
// (rules' frame_from_normal and sample_cosine_hemisphere; fixed seed), with
// tMin = the offset, as continue_paths.comp writes them. Both lists go
// through every contestant: facet's intersect kernel as the path loop runs it
// (PATHS = 1, indirect dispatch over the list), the ceiling's BVH4 of the same
// micro-grid's triangles, and Embree's rtcIntersect1 over those triangles.
// Times are medians of `repeats` interleaved passes after an untimed one;
// ratios are medians of each pass's ratio. Where the time goes: the nodes and
// cells (triangles) per ray, from counted copies of both traversals.
#pragma once

#include <string>
#include <vector>

namespace facet::benchmarks::incoherent {

struct Options {
  std::vector<std::string> cages;  // OBJ paths relative to the source tree
  int size = 512;
  int repeats = 11;
  int threads = 2;  // Embree's
  std::string adapter;
  std::string csvPath;
};

// Prints the tables; returns false where the contestants disagree on over 5 % of a list's hits.
bool runIncoherent(const Options& options);

}  // namespace facet::benchmarks::incoherent

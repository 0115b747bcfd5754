// One row of raycast_bench's results (an engine and method on one cage at
// one size), and how its numbers are written in the tables.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "analysis/image_compare.h"

namespace facet::benchmarks::raycast {

struct Row {
  std::string cage;
  int patches = 0;  // facet: limit patches after isolation; Embree: cage faces
  int size = 0;
  std::string engine;                                          // facet-gpu, facet-cpu, embree, embree8
  std::string method;                                          // exact, tess k=.., rate=..
  double refineMs = std::numeric_limits<double>::quiet_NaN();  // refine + BVH, or Embree commit
  double primaryMs = std::numeric_limits<double>::quiet_NaN();
  double shadowMs = std::numeric_limits<double>::quiet_NaN();
  double traceMs = std::numeric_limits<double>::quiet_NaN();  // every stage after refine + BVH
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  analysis::DepthError error;
  std::string stages;  // "name=ms;..."
  std::string note;

  double primaryMrays() const { return primaryRays / (primaryMs * 1e3); }
  double shadowMrays() const { return shadowRays / (shadowMs * 1e3); }
  double allMrays() const { return (primaryRays + shadowRays) / (traceMs * 1e3); }
};

std::string fmt(double v, const char* format = "%.1f");

std::string fmtSci(double v);

// Embree's rows: "embree" casts one rtcIntersect1 per pixel, "embree8" one
// rtcIntersect8 per 4×2 pixel tile (the same rays).
inline const std::string kEmbreeEngines[] = {"embree", "embree8"};

}  // namespace facet::benchmarks::raycast

// What raycast_bench --incoherent prints and writes: per scene and ray list,
// the rates of facet, the ceiling and Embree on the same rays, the ratios of
// one run, and the traversal work per ray.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace facet::benchmarks::incoherent {

// What a traversal did, per ray of a list (counted copies of the kernels).
// A step is one iteration of the traversal's loop: a node or a leaf. On
// lavapipe a SIMD group of kLanes consecutive invocations loops until its
// longest ray is done: groupSteps is the mean over rays of their group's
// longest, steps / groupSteps the lanes' utilisation.
constexpr int kLanes = 8;  // llvmpipe's 256-bit vectors, 32-bit lanes
struct WorkStats {
  double nodes = 0, leaves = 0, items = 0, steps = 0, groupSteps = 0;
};

struct Row {
  std::string scene;
  int k = 0;  // the dicing rate
  std::size_t triangles = 0;
  std::string rays;  // camera, camera hits, continuation
  std::size_t count = 0;
  double hitFraction = 0;
  double facetMs = 0, ceilingMs = 0, embreeMs = 0;      // medians
  double facetOverCeiling = 0, facetOverEmbree = 0;     // medians of each pass's rate ratio
  std::size_t facetVsCeiling = 0, embreeVsCeiling = 0;  // rays whose hits disagree
  WorkStats facetWork, ceilingWork;
  double mrays(double ms) const { return double(count) / (ms * 1e3); }
};

struct Report {
  std::string adapter;
  int size = 0, repeats = 0, threads = 0;
  std::vector<Row> rows;
  double seconds = 0;
};

void printReport(const Report& report);

void writeReportCsv(const std::string& path, const Report& report);

}  // namespace facet::benchmarks::incoherent

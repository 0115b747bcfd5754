// The Pareto section's points: one setting rendered and timed against the
// scenario's converged reference, and Embree 3's tessellation rates beside
// them where it is found.
#pragma once

#include <string>
#include <vector>

#include "analysis/bench/pareto_scenarios.h"

namespace facet::analysis::bench::pareto {

struct Point {
  std::string backend;  // gpu, cpu, embree
  Setting setting;
  double milliseconds = 0;
  ImageError error;
  Image image;  // empty for Embree, which returns depth alone
};

// CPU, exact at the default ε (1e-9 of each object's diagonal), same size and
// samples per pixel; sampled IBL with many pairs where the scene's lighting is
// the knob.
RenderReport renderReference(Renderer& renderer, const Scenario& s);

Point measure(Renderer& renderer, const Scenario& s, const Setting& setting, Backend backend, const Image& reference,
              const BenchOptions& options);

#if FACET_HAVE_EMBREE
// Embree answers depth alone: its candidate image carries its coverage and
// depth and the reference's normals, so only depth, holes and extra pixels
// differ.
struct EmbreeRun {
  std::vector<Point> points;
  std::string notes;  // where Embree's surface departs from facet's
};

EmbreeRun measureEmbree(const Scenario& s, const Sizes& sizes, const Image& reference, const BenchOptions& options);
#endif

}  // namespace facet::analysis::bench::pareto

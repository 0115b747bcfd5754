// The stability section's renders: the methods a sweep compares, the
// tolerances each is held to, and the runner that renders one column of a
// sweep with every method against the CPU exact reference.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/bench/stability_map.h"
#include "scenes/scene.h"

namespace facet::analysis::bench::stability {

constexpr int kTessellationRate = 8;
// Dense enough that its chords are far below a pixel here: the coverage
// against which an exact method's misses count as Newton failures.
constexpr int kCoverageRate = 24;

struct Method {
  std::string label;
  Backend backend = Backend::Cpu;
  scene::IntersectionMethod intersection = scene::IntersectionMethod::Exact;
  std::string lighting;  // a key the sweep's lighting function understands; "" for its default
};

// Per-method tolerances: the tessellated method's depth and normal differ
// from the limit surface by its chord error, which is its design, not a
// failure. Its bounds sit a margin above the chord error of k = 8 on these
// cages at scale 1 and the origin, so that what fails is what the condition
// broke.
struct Tolerances {
  Tolerance exact;
  Tolerance tessellated{5e-3, 0.1, 5e-2};
  const Tolerance& of(scene::IntersectionMethod m) const {
    return m == scene::IntersectionMethod::Exact ? exact : tessellated;
  }
};

std::string methodsText(const Tolerances& t);

class Runner {
 public:
  Runner(Renderer& renderer, const BenchOptions& options)
      : renderer_(renderer), options_(options), size_(options.quick ? 24 : 128) {}

  int size() const { return size_; }
  bool quick() const { return options_.quick; }
  const std::filesystem::path& root() const { return options_.root; }

  scene::Scene sceneOf(scene::ControlCage cage) const;

  Image render(scene::Scene scene, const Method& method, double* milliseconds = nullptr);

  // Renders `scene` at column `column` of `sweep` with every method, each
  // against the CPU exact render with the same lighting. `light` sets a
  // method's lighting on a copy of the scene; `newton` adds the dense
  // coverage that Newton misses are counted against; `converged`, when set,
  // gives the reference each cell's methodError is measured against.
  void run(Sweep& sweep, std::size_t column, const scene::Scene& scene, const std::vector<Method>& methods,
           const std::function<void(scene::Scene&, const std::string&)>& light, bool newton,
           const std::function<Image()>& converged = {});

  const Tolerances& tolerances() const { return tolerances_; }
  int renders() const { return renders_; }

 private:
  Renderer& renderer_;
  const BenchOptions& options_;
  int size_;
  Tolerances tolerances_;
  int renders_ = 0;
};

}  // namespace facet::analysis::bench::stability

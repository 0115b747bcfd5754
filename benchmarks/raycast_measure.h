// raycast_bench's measurements: facet's four methods on every cage at every
// size, and Embree 3's tessellation rates beside them where it is found, each
// with its depth error against facet's CPU exact depth image.
#pragma once

#include <string>
#include <vector>

#include "benchmarks/raycast_rows.h"
#include "engine/renderer.h"
#include "scenes/control_cage.h"

namespace facet::benchmarks::raycast {

constexpr int kThreads = 2;

struct NamedCage {
  std::string name;
  scene::ControlCage cage;
};

struct Measurements {
  std::vector<Row> rows;
  std::vector<std::string> skipped;  // what was left out, and why
  std::vector<std::string> checks;   // --quick: embree8's depth against embree's
  bool checksPassed = true;
  double seconds = 0;  // the whole run, the warm-up included
};

// `allRates` are Embree's tessellation rates before each cage's grid budget
// cuts them; `quick` adds the checks of rtcIntersect8 against rtcIntersect1.
Measurements measureAll(Renderer& renderer, const std::vector<NamedCage>& cages, const std::vector<int>& sizes,
                        const std::vector<int>& allRates, bool quick);

}  // namespace facet::benchmarks::raycast

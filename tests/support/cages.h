#pragma once
// The torture cages of scenes/cages, loaded for tests, and one-face cages
// built in place.

#include "scenes/obj_cage.h"

#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <cmath>

#include <string>
#include <vector>

namespace facet::scene::testing {

inline const std::vector<std::string>& tortureCageNames() {
  static const std::vector<std::string> names = {"cube",          "valence_3_to_10", "pole24",
                                                 "boundary_hole", "creased_box",     "ngon_prism",
                                                 "thin_slab",     "nearly_flat",     "suzanne"};
  return names;
}

inline ControlCage loadTortureCage(const std::string& name) {
  return loadObjCage(std::string(FACET_CAGE_DIR) + "/" + name + ".obj");
}

// One face through `positions`, in their order.
inline ControlCage singleFace(std::vector<glm::dvec3> positions) {
  ControlCage cage;
  cage.source = "single face";
  cage.faceVertexCounts = {int(positions.size())};
  for (int i = 0; i < int(positions.size()); ++i) cage.faceVertexIndices.push_back(i);
  cage.positions = std::move(positions);
  return cage;
}

// A torus about +y of radii `major` and `minor`: `around` x `across` quads.
inline ControlCage torusCage(int around, int across, double major, double minor) {
  ControlCage cage;
  cage.source = "torus";
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const double phi = 2 * glm::pi<double>() * i / around, theta = 2 * glm::pi<double>() * j / across;
      const double r = major + minor * std::cos(theta);
      cage.positions.push_back({r * std::cos(phi), minor * std::sin(theta), r * std::sin(phi)});
    }
  auto at = [&](int a, int b) { return (a % around) * across + b % across; };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      cage.faceVertexCounts.push_back(4);
      for (int v : {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)}) cage.faceVertexIndices.push_back(v);
    }
  return cage;
}

}  // namespace facet::scene::testing

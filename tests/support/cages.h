#pragma once
// The torture cages of scenes/cages, loaded for tests, and one-face cages
// built in place.

#include "scenes/obj_cage.h"

#include <glm/vec3.hpp>

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

}  // namespace facet::scene::testing

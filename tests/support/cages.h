#pragma once
// The torture cages of scenes/cages, loaded for tests.

#include "scenes/obj_cage.h"

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

}  // namespace facet::scene::testing

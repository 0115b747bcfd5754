// Where `facet` finds the scenes, cages and environments its charts and
// benchmarks use by default: the folder that holds scenes/.
#pragma once

#include <filesystem>

namespace facet::cli {

// share/facet of the prefix the binary is installed under, or, for the
// binary of a build tree, the share/facet its configure step links beside
// it. Throws std::invalid_argument, naming both, where neither holds scenes/.
std::filesystem::path dataFolder();

}  // namespace facet::cli

// What a render does differently from what its files say (scenes/scene.h's
// warnings, and an environment's clamped texels), once each: on stderr
// unless --quiet or --json, and kept in --json's "warnings".
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace facet::cli {

std::vector<std::string> sceneWarnings(const scene::Scene& scene);

// One line "facet: warning: ..." per warning, unless `quiet`.
void printWarnings(const std::vector<std::string>& warnings, bool quiet);

}  // namespace facet::cli

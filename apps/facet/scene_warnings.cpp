#include "scene_warnings.h"

#include <cstdio>

namespace facet::cli {

void printSceneWarnings(const scene::Scene& scene) {
  for (const std::string& warning : scene.warnings) std::fprintf(stderr, "facet: warning: %s\n", warning.c_str());
}

}  // namespace facet::cli

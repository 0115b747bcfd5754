#include "scene_warnings.h"

#include <cstdio>

namespace facet::cli {

std::vector<std::string> sceneWarnings(const scene::Scene& scene) {
  std::vector<std::string> warnings = scene.warnings;
  if (scene.environment && scene.environment->map->clampedTexels > 0)
    warnings.push_back(scene.environment->map->source.string() + ": " +
                       std::to_string(scene.environment->map->clampedTexels) +
                       " texels were negative, NaN or Inf and are set to 0");
  return warnings;
}

void printWarnings(const std::vector<std::string>& warnings, bool quiet) {
  if (quiet) return;
  for (const std::string& warning : warnings) std::fprintf(stderr, "facet: warning: %s\n", warning.c_str());
}

}  // namespace facet::cli

// The preview's objects (scenes/examples/preview.json), close enough to
// light each other, under the courtyard with its shadow rays, small: a scene
// whose paths go from object to object. Needs FACET_EXAMPLES_DIR and
// FACET_ENVIRONMENTS_DIR.
#pragma once

#include <filesystem>
#include <memory>

#include "scenes/environment_map.h"
#include "scenes/scene.h"
#include "scenes/scene_file.h"

namespace facet::testing {

inline scene::Scene previewWithPaths(scene::IntersectionMethod method, int bounces) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json");
  s.lights.clear();
  s.render.width = 48;
  s.render.height = 24;
  s.render.method = method;
  s.render.bounces = bounces;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / "courtyard_256x128.hdr"));
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->occlusion = true;
  s.environment->samples = 2;
  return s;
}

}  // namespace facet::testing

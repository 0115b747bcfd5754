// The cube cage's limit surface (convex, so no shadow ray finds it again)
// under an environment and no punctual light, size x size pixels, for the
// image-based-lighting and camera-sample tests. Needs FACET_CAGE_DIR.
#pragma once

#include <filesystem>
#include <memory>
#include <utility>

#include "scenes/obj_cage.h"
#include "scenes/scene.h"

namespace facet::testing {

inline scene::Scene blobUnder(const materials::Material& material, std::shared_ptr<const scene::EnvironmentMap> map,
                              int size) {
  scene::Scene s;
  s.materials.push_back(material);
  scene::Object blob;
  blob.name = "blob";
  blob.cage = scene::loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  s.objects.push_back(std::move(blob));
  s.camera.eye = {1.5, 1.0, 3.5};
  s.camera.verticalFovDegrees = 30;
  s.render.width = s.render.height = size;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.environment.emplace();
  s.environment->map = std::move(map);
  return s;
}

}  // namespace facet::testing

// A Lambertian material, and the cube cage's limit surface (convex, so no
// shadow ray finds it again) under an environment and no punctual light,
// size x size pixels, for the image-based-lighting, camera-sample and path
// tests. Needs FACET_CAGE_DIR.
#pragma once

#include <filesystem>
#include <memory>
#include <utility>

#include "scenes/obj_cage.h"
#include "scenes/scene.h"
#include "scenes/scene_file.h"

namespace facet::testing {

// No specular lobe at all: a dielectric of index 1 is no interface (F = 0
// at every angle, where Schlick's F would still rise at grazing).
inline materials::Material lambertian(double albedo) {
  materials::Material m = scene::defaultMaterial();
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.eta = glm::dvec3(1.0);
  m.diffuse = glm::dvec3(albedo);
  return m;
}

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

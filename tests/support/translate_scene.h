#pragma once
// A scene moved rigidly by `offset`: cages, lights and camera together, so
// the image stays the same while the coordinates grow.

#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace facet::testing {

inline void translateScene(scene::Scene& scene, const glm::dvec3& offset) {
  for (scene::Object& object : scene.objects)
    for (glm::dvec3& p : object.cage.positions) p += offset;
  for (scene::Light& light : scene.lights) light.position += offset;
  scene.camera.eye += offset;
  scene.camera.target += offset;
}

}  // namespace facet::testing

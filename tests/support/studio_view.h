#pragma once
// A scene as a test looks at it: from a camera of its choosing, lit by the
// default studio, square, four samples a pixel.

#include "scenes/scene.h"
#include "scenes/studio_environment.h"

namespace facet::testing {

inline scene::Scene studioView(scene::Scene scene, const scene::Camera& camera, int size) {
  scene.camera = camera;
  scene.environment = scene::studioEnvironment();
  scene.render.width = scene.render.height = size;
  scene.render.samplesPerPixel = 4;
  return scene;
}

}  // namespace facet::testing

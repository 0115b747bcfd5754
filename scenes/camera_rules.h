// The rule a camera must meet to take a picture, one for every place a camera
// comes from: scene files, the command line, the APIs and the cameras that
// camera keys interpolate between frames.
#pragma once

#include <glm/geometric.hpp>

#include "scenes/scene.h"

namespace facet::scene {

// Why `camera` cannot take a picture, or nullptr when it can: the view
// direction must exist (eye and target apart, their distance finite) and up
// must be neither zero nor parallel to it, else the camera has no frame.
inline const char* cameraProblem(const Camera& camera) {
  const glm::dvec3 view = camera.target - camera.eye;
  const double distance = glm::length(view);
  if (!(distance < 1e300)) return "eye and target are too far apart (or not finite)";
  if (distance < 1e-12) return "eye and target must differ";
  const double upLength = glm::length(camera.up);
  if (!(upLength > 0.0) || !(glm::length(glm::cross(view / distance, camera.up / upLength)) >= 1e-9))
    return "up must not be zero or parallel to the view direction";
  return nullptr;
}

}  // namespace facet::scene

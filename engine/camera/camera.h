// C++ side of compute/shared/camera.h, in double for the CPU reference.
#pragma once

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

#include "scenes/scene.h"

namespace facet::camera {

using real = double;
using vec3 = glm::dvec3;
using glm::normalize;
#define FACET_FN inline
#include "compute/shared/camera.h"
#undef FACET_FN

inline CameraFrame cameraFrame(const scene::Camera& camera, int width, int height) {
  CameraFrame frame;
  frame.eye = camera.eye;
  frame.forward = glm::normalize(camera.target - camera.eye);
  frame.right = glm::normalize(glm::cross(frame.forward, camera.up));
  frame.up = glm::cross(frame.right, frame.forward);
  frame.tanHalfFovY = std::tan(glm::radians(0.5 * camera.verticalFovDegrees));
  frame.aspect = double(width) / double(height);
  return frame;
}

}  // namespace facet::camera

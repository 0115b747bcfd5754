// The scene's camera as the frame of the pinhole rule (rules/camera/camera.h),
// in double for the CPU reference and the host side of the GPU path.
#pragma once

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

#include "rules/rules.h"
#include "scenes/scene.h"

namespace facet::camera {

inline rules::f64::CameraFrame cameraFrame(const scene::Camera& camera, int width, int height) {
  rules::f64::CameraFrame frame;
  frame.eye = camera.eye;
  frame.forward = glm::normalize(camera.target - camera.eye);
  frame.right = glm::normalize(glm::cross(frame.forward, camera.up));
  frame.up = glm::cross(frame.right, frame.forward);
  frame.tanHalfFovY = std::tan(glm::radians(0.5 * camera.verticalFovDegrees));
  frame.aspect = double(width) / double(height);
  return frame;
}

}  // namespace facet::camera

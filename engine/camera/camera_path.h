// The camera of frame f of an animation: keyframes interpolated.
#pragma once

#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

#include "scenes/scene.h"

namespace facet::camera {

// Eye, target, up and field of view linear between the keys around `frame`;
// held before the first key and after the last. `keys` is sorted by frame.
inline scene::Camera keyedCamera(const std::vector<scene::CameraKey>& keys, double frame) {
  if (frame <= keys.front().frame) return keys.front().camera;
  if (frame >= keys.back().frame) return keys.back().camera;
  const auto next = std::upper_bound(keys.begin(), keys.end(), frame,
                                     [](double f, const scene::CameraKey& key) { return f < key.frame; });
  const scene::CameraKey& a = *(next - 1);
  const scene::CameraKey& b = *next;
  // In double: keys may lie more than 2^31 frames apart.
  const double t = (frame - double(a.frame)) / (double(b.frame) - double(a.frame));
  scene::Camera c;
  c.eye = glm::mix(a.camera.eye, b.camera.eye, t);
  c.target = glm::mix(a.camera.target, b.camera.target, t);
  c.up = glm::mix(a.camera.up, b.camera.up, t);
  c.verticalFovDegrees = a.camera.verticalFovDegrees + t * (b.camera.verticalFovDegrees - a.camera.verticalFovDegrees);
  return c;
}

}  // namespace facet::camera

// A scene's punctual light as the shared rules take it
// (rules/shading/lights.h): cone angles as their cosines.
#pragma once

#include <glm/trigonometric.hpp>

#include <cmath>

#include "rules/rules.h"
#include "scenes/scene.h"

namespace facet::cpu {

inline rules::f64::PunctualLight punctualLight(const scene::Light& light) {
  rules::f64::PunctualLight p;
  p.directional = light.type == scene::LightType::Directional;
  p.spot = light.type == scene::LightType::Spot;
  p.position = light.position;
  p.direction = light.direction;
  p.color = light.color;
  p.cos_inner = std::cos(glm::radians(light.innerConeDegrees));
  p.cos_outer = std::cos(glm::radians(light.outerConeDegrees));
  return p;
}

}  // namespace facet::cpu

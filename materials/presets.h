// The F(0) tables of the SIGGRAPH 2010 course "Physically Based Shading
// Models for Film and Game Production" (Hoffman, background talk), every row
// with its values exactly as printed.
#pragma once

#include <glm/vec3.hpp>

#include <limits>
#include <span>
#include <string_view>

namespace facet::materials {

struct Preset {
  std::string_view name;   // identifier used by the CLI and material files
  std::string_view label;  // as printed in the course
  bool metal;              // metals have no diffuse term
  glm::dvec3 f0_linear;    // F(0) linear, as printed
  glm::dvec3 f0_srgb;      // F(0) sRGB, as printed (for checking only)
  // Not the course's: the transparent insulators transmit (docs/shading.md,
  // "Transmission"), ruby absorbing all but red over attenuationDistance.
  double transmission = 0.0;
  glm::dvec3 attenuationColor{1.0};
  double attenuationDistance = std::numeric_limits<double>::infinity();
};

std::span<const Preset> presets();
// nullptr when there is no preset of that name.
const Preset* findPreset(std::string_view name);

// Relative index of refraction of the dielectric whose normal-incidence
// reflectance is f0: the inverse of f0 = ((eta - 1) / (eta + 1))^2, eta > 1.
double iorFromF0(double f0);

}  // namespace facet::materials

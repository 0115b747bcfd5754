#include "materials/presets.h"

#include <cmath>

namespace facet::materials {

namespace {

constexpr Preset kPresets[] = {
    {"gold", "Gold", true, {1.00, 0.71, 0.29}, {1.00, 0.86, 0.57}},
    {"silver", "Silver", true, {0.95, 0.93, 0.88}, {0.98, 0.97, 0.95}},
    {"copper", "Copper", true, {0.95, 0.64, 0.54}, {0.98, 0.82, 0.76}},
    {"iron", "Iron", true, {0.56, 0.57, 0.58}, {0.77, 0.78, 0.78}},
    {"aluminum", "Aluminum", true, {0.91, 0.92, 0.92}, {0.96, 0.96, 0.97}},
    {"water", "Water", false, {0.02, 0.02, 0.02}, {0.15, 0.15, 0.15}, 1.0},
    {"plastic-glass-low", "Plastic / Glass (Low)", false, {0.03, 0.03, 0.03}, {0.21, 0.21, 0.21}, 1.0},
    {"plastic-high", "Plastic High", false, {0.05, 0.05, 0.05}, {0.24, 0.24, 0.24}},
    {"glass-high-ruby",
     "Glass (High) / Ruby",
     false,
     {0.08, 0.08, 0.08},
     {0.31, 0.31, 0.31},
     1.0,
     {0.9, 0.15, 0.2},
     1.0},
    {"diamond", "Diamond", false, {0.17, 0.17, 0.17}, {0.45, 0.45, 0.45}, 1.0},
};

}  // namespace

std::span<const Preset> presets() { return kPresets; }

const Preset* findPreset(std::string_view name) {
  for (const Preset& preset : kPresets)
    if (preset.name == name) return &preset;
  return nullptr;
}

double iorFromF0(double f0) {
  double r = std::sqrt(f0);
  return (1.0 + r) / (1.0 - r);
}

}  // namespace facet::materials

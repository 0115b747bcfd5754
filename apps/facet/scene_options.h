// Command-line flags that change a scene as loaded (render, parity,
// ibl-chart): image size, camera, intersection method, sampling, the
// environment and energy compensation.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/pixel_rect.h"
#include "scenes/scene.h"

namespace facet::cli {

// Every field shapes the scene: parity's reference key names each
// (cmd_parity.cpp, shapedBy).
struct SceneOverrides {
  std::string size;
  std::vector<double> eye, target, up;
  std::optional<double> fov;
  std::string method;
  std::optional<int> tessLevel;
  std::optional<int> spp;
  std::optional<int> bounces;
  std::optional<int> diffuseBounces, glossyBounces, transmissionBounces;  // per lobe kind
  std::string subdivision;
  std::string environment;
  std::optional<double> environmentIntensity;
  std::optional<double> environmentRotation;
  std::string ibl;
  std::optional<int> iblSamples;
  std::string occlusion;
  std::optional<std::uint32_t> seed;
  std::string energyCompensation;
};

void addSceneOverrideOptions(CLI::App& command, SceneOverrides& overrides);

// --env, --env-intensity and --env-rotation alone.
void addEnvironmentOptions(CLI::App& command, SceneOverrides& overrides);

// Command-line settings win over the scene file's; throws
// std::invalid_argument naming the flag.
void applySceneOverrides(const SceneOverrides& overrides, scene::Scene& scene);

// The warning for a seed given (`given`: "--seed 3") to a scene without an
// environment, whose random numbers are fixed.
std::string seedChangesNothing(const std::string& given);

// --energy-compensation on|off alone: sets every material's flag; "" keeps
// what the scene chose.
void addEnergyCompensationOption(CLI::App& command, std::string& onOrOff);
void applyEnergyCompensation(const std::string& onOrOff, scene::Scene& scene);

// --size WIDTHxHEIGHT and --method exact|tess alone.
void applyImageSize(const std::string& size, scene::Scene& scene);
void applyMethod(const std::string& method, scene::Scene& scene);

// One line for people: the map, its size and the lighting method.
std::string describeEnvironment(const scene::Environment& environment);

}  // namespace facet::cli

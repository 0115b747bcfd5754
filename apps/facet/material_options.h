// Command-line flags that describe a material (shared by brdf, albedo and
// plot): --d --g --f --f0 --ior --eta --k --alpha --roughness --diffuse
// --preset, or --material FILE.json.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "materials/material.h"

namespace facet::cli {

struct MaterialOptions {
  std::optional<std::string> d, g, f, f0, ior, eta, k, alpha, roughness, diffuse, preset;
  std::optional<std::string> material_file;
};

// A sub-command of `parent` that takes the material flags into `options`.
CLI::App* addMaterialCommand(CLI::App& parent, const std::string& name, const std::string& description,
                             MaterialOptions& options);

// Validated material; throws std::invalid_argument naming the flag (or the
// file and field) and the rule.
materials::Material resolveMaterial(const MaterialOptions& options);

// A finite number from a flag's text; throws naming the flag.
double parseNumber(const std::string& flag, const std::string& text);

}  // namespace facet::cli

// Command-line flags that describe a material (shared by brdf, albedo and
// plot): --d --g --f, a flag per row of the material parameter table that
// has one (--alpha, --f0, ..., --sheen-roughness), --preset, or --material
// FILE.json; and render's flags that change a model's materials and fields:
// --material [OBJECT=]FILE|PRESET, --set.
#pragma once

#include <CLI/CLI.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "materials/material.h"
#include "materials/parameter_table.h"
#include "scenes/scene.h"

namespace facet::cli {

struct MaterialOptions {
  std::optional<std::string> d, g, f, preset;
  // By row of materials/parameter_table.h; a row without a flag stays empty.
  std::array<std::optional<std::string>, materials::kMaterialParameterCount> parameters;
  std::optional<std::string> material_file;
};

// A sub-command of `parent` that takes the material flags into `options`.
CLI::App* addMaterialCommand(CLI::App& parent, const std::string& name, const std::string& description,
                             MaterialOptions& options);

// Validated material; throws std::invalid_argument naming the flag (or the
// file and field) and the rule.
materials::Material resolveMaterial(const MaterialOptions& options);

// facet render's --material and --set, each repeatable, and --variant.
// Every field shapes the scene: parity's reference key names each
// (cmd_parity.cpp, shapedBy).
struct SceneEdits {
  std::vector<std::string> materials;  // [OBJECT=]FILE|PRESET
  std::vector<std::string> sets;       // PATH=VALUE
  std::string variant;                 // a glTF file's material variant, by name
};

void addSceneEditOptions(CLI::App& command, SceneEdits& edits);

// A material reference as --material and facet preview take it: a file, a
// preset, or a bare name of the shipped library, NAME.json in
// scenes/examples/materials of the data folder (data_folder.h), which a
// name that is no preset and no file resolves to where it exists.
std::string libraryMaterialReference(const std::string& reference);

// The scene at `path` with the --set overrides read into it and the
// --material materials on its objects (docs/scene-format.md, "Material
// files" and "The command line: --material and --set"); throws naming the
// flag, or the file and field.
scene::Scene loadEditedScene(const std::string& path, const SceneEdits& edits);

// A finite number from a flag's text; throws naming the flag.
double parseNumber(const std::string& flag, const std::string& text);

}  // namespace facet::cli

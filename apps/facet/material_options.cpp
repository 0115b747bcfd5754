#include "material_options.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "data_folder.h"
#include "materials/models.h"
#include "materials/presets.h"
#include "scenes/json_overrides.h"
#include "scenes/scene_file.h"

namespace facet::cli {

namespace {

// "x" or "r,g,b".
glm::dvec3 parseColor(const std::string& flag, const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) values.push_back(parseNumber(flag, item));
  if (values.size() == 1) return glm::dvec3(values[0]);
  if (values.size() != 3)
    throw std::invalid_argument(flag +
                                ": expected one number or three comma-separated numbers "
                                "r,g,b, got '" +
                                text + "'");
  return {values[0], values[1], values[2]};
}

std::string flagFor(std::string_view field) {
  if (field == "distribution") return "--d";
  if (field == "geometry") return "--g";
  if (field == "fresnel") return "--f";
  std::string flag = "--" + std::string(field);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

}  // namespace

double parseNumber(const std::string& flag, const std::string& text) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    throw std::invalid_argument(flag + ": expected a finite number, got '" + text + "'");
  return value;
}

namespace {

void addMaterialOptions(CLI::App& command, MaterialOptions& o) {
  using materials::modelList;
  command.add_option("--d", o.d, "normal distribution: " + modelList(materials::kDistributions) + " (default ggx)");
  command.add_option("--g", o.g,
                     "shadowing-masking: " + modelList(materials::kGeometryTerms) + " (default smith-ggx-correlated)");
  command.add_option(
      "--f", o.f,
      "Fresnel: " + modelList(materials::kFresnelTerms) + " (default schlick if F(0) or a preset is given, else none)");
  materials::forEachParameterIndexed([&](const auto& row, std::size_t i) {
    if (row.flagHelp) command.add_option(flagFor(row.key), o.parameters[i], row.flagHelp);
  });
  command.add_option("--preset", o.preset, "F(0) from a preset (see `facet presets`)");
  command.add_option("--material", o.material_file, "JSON material file instead of the flags above");
}

}  // namespace

CLI::App* addMaterialCommand(CLI::App& parent, const std::string& name, const std::string& description,
                             MaterialOptions& options) {
  CLI::App* command = parent.add_subcommand(name, description);
  addMaterialOptions(*command, options);
  return command;
}

materials::Material resolveMaterial(const MaterialOptions& o) {
  if (o.material_file) {
    const bool parameterGiven = std::ranges::any_of(o.parameters, [](const auto& text) { return text.has_value(); });
    if (o.d || o.g || o.f || o.preset || parameterGiven)
      throw std::invalid_argument("--material: cannot be combined with material flags");
    return materials::loadMaterial(*o.material_file);
  }
  materials::MaterialSpec spec;
  spec.preset = o.preset;
  // These commands evaluate the reflection BRDF alone: a transparent preset
  // is its course's opaque insulator here (docs/shading.md, "Transmission").
  spec.transmission = 0.0;
  spec.distribution = o.d;
  spec.geometry = o.g;
  spec.fresnel = o.f;
  // Only numbers and colours are flags (materials/material_parameters.h).
  materials::forEachParameterIndexed([&](const auto& row, std::size_t i) {
    const std::optional<std::string>& text = o.parameters[i];
    if (!text) return;
    using T = typename std::decay_t<decltype(row)>::Value;
    if constexpr (std::is_same_v<T, double>) spec.*row.spec = parseNumber(flagFor(row.key), *text);
    if constexpr (std::is_same_v<T, glm::dvec3>) spec.*row.spec = parseColor(flagFor(row.key), *text);
  });
  return materials::buildMaterial(spec, flagFor);
}

void addSceneEditOptions(CLI::App& command, SceneEdits& edits) {
  command
      .add_option("--material", edits.materials,
                  "A material on the model's objects: a material file (.json), a preset (see `facet presets`) or a "
                  "name of the shipped library (scenes/examples/materials: glass, glazed_ceramic, ...); "
                  "OBJECT=FILE|PRESET for the objects of that name (repeatable)")
      ->allow_extra_args(false);
  command
      .add_option("--set", edits.sets,
                  "PATH=VALUE: a field of the scene by its JSON path, e.g. render.spp=16, camera.fov=40, "
                  "materials.gold.roughness=0.2, objects[0].material=silver (repeatable)")
      ->allow_extra_args(false);
  command.add_option("--variant", edits.variant,
                     "A glTF file's material variant by name (KHR_materials_variants); without it each primitive "
                     "renders in its own material");
}

std::string libraryMaterialReference(const std::string& reference) {
  namespace fs = std::filesystem;
  std::error_code error;
  const bool bareName = reference.find_first_of("./") == std::string::npos;
  if (!bareName || materials::findPreset(reference) || fs::exists(reference, error)) return reference;
  try {
    const fs::path file = dataFolder() / "scenes" / "examples" / "materials" / (reference + ".json");
    return fs::is_regular_file(file, error) ? file.string() : reference;
  } catch (const std::invalid_argument&) {
    return reference;  // no data folder: the reference's own error names it
  }
}

scene::Scene loadEditedScene(const std::string& path, const SceneEdits& edits) {
  std::vector<scene::JsonOverride> overrides;
  for (const std::string& assignment : edits.sets) overrides.push_back(scene::parseJsonOverride(assignment));
  // Every object's material first, then the named objects', whatever the order given.
  std::vector<std::pair<std::string, std::string>> assignments;  // object (empty: every one), reference
  std::set<std::string> named;
  for (const std::string& value : edits.materials) {
    const std::size_t equals = value.find('=');
    std::string object = equals == std::string::npos ? "" : value.substr(0, equals);
    std::string reference = equals == std::string::npos ? value : value.substr(equals + 1);
    if (reference.empty() || (equals != std::string::npos && object.empty()))
      throw std::invalid_argument("--material '" + value + "': expected FILE, PRESET, OBJECT=FILE or OBJECT=PRESET");
    if (!named.insert(object).second)
      throw std::invalid_argument("--material '" + value + "': " +
                                  (object.empty() ? std::string("a material for every object is given twice")
                                                  : "object '" + object + "' is given a material twice"));
    assignments.emplace_back(std::move(object), std::move(reference));
  }
  std::stable_partition(assignments.begin(), assignments.end(), [](const auto& a) { return a.first.empty(); });

  scene::Scene scene = scene::loadScene(path, overrides, edits.variant);
  for (const auto& [object, reference] : assignments) {
    materials::Material material = scene::loadMaterialReference(libraryMaterialReference(reference), scene.textures);
    try {
      scene::assignMaterial(scene, object, std::move(material));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--material '" + object + "=" + reference + "': " + std::string(e.what()));
    }
  }
  return scene;
}

}  // namespace facet::cli

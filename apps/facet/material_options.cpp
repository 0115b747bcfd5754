#include "material_options.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "materials/models.h"
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
  if (field == "anisotropy_rotation") return "--anisotropy-rotation";
  if (field == "clearcoat_roughness") return "--clearcoat-roughness";
  if (field == "sheen_color") return "--sheen-color";
  if (field == "sheen_roughness") return "--sheen-roughness";
  if (field == "base_color") return "--base-color";
  return "--" + std::string(field);
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
  command.add_option("--f0", o.f0, "F(0) = c_spec for schlick (or to derive an ior): x or r,g,b");
  command.add_option("--ior", o.ior, "index of refraction for dielectric: x or r,g,b");
  command.add_option("--eta", o.eta, "conductor: real part of the complex index, r,g,b");
  command.add_option("--k", o.k, "conductor: extinction coefficient, r,g,b");
  command.add_option("--alpha", o.alpha, "microfacet alpha in [0, 1] (alpha = roughness^2)");
  command.add_option("--roughness", o.roughness, "perceptual roughness in [0, 1], instead of --alpha");
  command.add_option("--diffuse", o.diffuse, "Lambert c_diff: x or r,g,b (default 0)");
  command.add_option("--base-color", o.baseColor,
                     "glTF's base colour, linear r,g,b or x in [0, 1], with --metallic: instead of --diffuse and --f0");
  command.add_option("--metallic", o.metallic, "glTF's metallic in [0, 1], with --base-color");
  command.add_option("--anisotropy", o.anisotropy,
                     "anisotropy strength in [0, 1]: alpha along the tangent (the x axis) = mix(alpha, 1, s^2)");
  command.add_option("--anisotropy-rotation", o.anisotropyRotation,
                     "the tangent's rotation about the normal from the x axis, radians");
  command.add_option("--clearcoat", o.clearcoat, "clear coat strength in [0, 1]: a GGX lobe of F(0) = 0.04 on top");
  command.add_option("--clearcoat-roughness", o.clearcoatRoughness, "the clear coat's perceptual roughness in [0, 1]");
  command.add_option("--sheen-color", o.sheenColor,
                     "sheen color, linear RGB in [0, 1] (r,g,b or one value): a Charlie lobe between base and coat");
  command.add_option("--sheen-roughness", o.sheenRoughness, "the sheen's roughness in [0, 1]");
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
    if (o.d || o.g || o.f || o.f0 || o.ior || o.eta || o.k || o.alpha || o.roughness || o.diffuse || o.baseColor ||
        o.metallic || o.preset || o.anisotropy || o.anisotropyRotation || o.clearcoat || o.clearcoatRoughness ||
        o.sheenColor || o.sheenRoughness)
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
  if (o.alpha) spec.alpha = parseNumber("--alpha", *o.alpha);
  if (o.roughness) spec.roughness = parseNumber("--roughness", *o.roughness);
  if (o.f0) spec.f0 = parseColor("--f0", *o.f0);
  if (o.ior) spec.ior = parseColor("--ior", *o.ior);
  if (o.eta) spec.eta = parseColor("--eta", *o.eta);
  if (o.k) spec.k = parseColor("--k", *o.k);
  if (o.diffuse) spec.diffuse = parseColor("--diffuse", *o.diffuse);
  if (o.baseColor) spec.baseColor = parseColor("--base-color", *o.baseColor);
  if (o.metallic) spec.metallic = parseNumber("--metallic", *o.metallic);
  if (o.anisotropy) spec.anisotropy = parseNumber("--anisotropy", *o.anisotropy);
  if (o.anisotropyRotation) spec.anisotropyRotation = parseNumber("--anisotropy-rotation", *o.anisotropyRotation);
  if (o.clearcoat) spec.clearcoat = parseNumber("--clearcoat", *o.clearcoat);
  if (o.clearcoatRoughness) spec.clearcoatRoughness = parseNumber("--clearcoat-roughness", *o.clearcoatRoughness);
  if (o.sheenColor) spec.sheenColor = parseColor("--sheen-color", *o.sheenColor);
  if (o.sheenRoughness) spec.sheenRoughness = parseNumber("--sheen-roughness", *o.sheenRoughness);
  return materials::buildMaterial(spec, flagFor);
}

void addSceneEditOptions(CLI::App& command, SceneEdits& edits) {
  command
      .add_option("--material", edits.materials,
                  "A material on the model's objects: a material file (.json) or a preset (see `facet presets`); "
                  "OBJECT=FILE|PRESET for the objects of that name (repeatable)")
      ->allow_extra_args(false);
  command
      .add_option("--set", edits.sets,
                  "PATH=VALUE: a field of the scene by its JSON path, e.g. render.spp=16, camera.fov=40, "
                  "materials.gold.roughness=0.2, objects[0].material=silver (repeatable)")
      ->allow_extra_args(false);
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

  scene::Scene scene = scene::loadScene(path, overrides);
  for (const auto& [object, reference] : assignments) {
    materials::Material material = scene::loadMaterialReference(reference, scene.textures);
    try {
      scene::assignMaterial(scene, object, std::move(material));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--material '" + object + "=" + reference + "': " + std::string(e.what()));
    }
  }
  return scene;
}

}  // namespace facet::cli

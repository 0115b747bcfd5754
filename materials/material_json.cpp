// A material's JSON form (docs/shading.md, "Materials"): the keys a file
// may hold, read into a MaterialSpec, and a built material written back.
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <type_traits>

#include "materials/material.h"
#include "materials/models.h"
#include "materials/parameter_table.h"
#include "materials/strict_json.h"

namespace facet::materials {

namespace {

// The keys a material file may hold, in the order an unknown key's error
// lists them: the name and the models' names, then every parameter's.
constexpr auto kKeys = [] {
  std::array<const char*, 5 + kMaterialParameterCount> keys{"name", "preset", "distribution", "geometry", "fresnel"};
  std::size_t i = 5;
  forEachParameter([&](const auto& row) { keys[i++] = row.key; });
  return keys;
}();

}  // namespace

MaterialSpec materialSpecFromJson(const nlohmann::json& json, std::string_view source) {
  auto fail = [&](std::string_view field, const std::string& rule) {
    throw std::invalid_argument(std::string(source) + ": field '" + std::string(field) + "': " + rule);
  };
  if (!json.is_object()) throw std::invalid_argument(std::string(source) + ": a material must be a JSON object");
  if (const std::optional<std::string> key = findUnknownKey(json, kKeys)) fail(*key, unknownFieldRule(kKeys));
  auto text = [&](const std::string& key) -> std::optional<std::string> {
    if (!json.contains(key)) return std::nullopt;
    if (!json[key].is_string()) fail(key, "expected a string");
    return json[key].get<std::string>();
  };

  MaterialSpec spec;
  spec.name = text("name").value_or("");
  spec.preset = text("preset");
  spec.distribution = text("distribution");
  spec.geometry = text("geometry");
  spec.fresnel = text("fresnel");
  forEachParameter([&](const auto& row) {
    if (!json.contains(row.key)) return;
    const nlohmann::json& value = json[row.key];
    using T = typename std::decay_t<decltype(row)>::Value;
    if constexpr (std::is_same_v<T, double>) {
      if (!value.is_number()) fail(row.key, "expected a number");
      spec.*row.spec = value.get<double>();
    } else if constexpr (std::is_same_v<T, bool>) {
      if (!value.is_boolean()) fail(row.key, "expected true or false");
      spec.*row.spec = value.get<bool>();
    } else {
      static_assert(std::is_same_v<T, glm::dvec3>);
      if (value.is_number()) {
        spec.*row.spec = glm::dvec3(value.get<double>());
        return;
      }
      if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
          !value[2].is_number())
        fail(row.key, "expected a number or an array of 3 numbers (r, g, b)");
      spec.*row.spec = glm::dvec3(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
    }
  });
  return spec;
}

Material loadMaterial(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path.string() + ": cannot open material file");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // syntax errors, and numbers beyond double's range
    throw std::invalid_argument(path.string() + ": not valid JSON: " + e.what());
  }
  const std::string source = path.string();
  return buildMaterial(materialSpecFromJson(json, source),
                       [&](std::string_view field) { return source + ": field '" + std::string(field) + "'"; });
}

nlohmann::json toJson(const Material& m) {
  auto array = [](glm::dvec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  nlohmann::json json = {
      {"distribution", modelName(kDistributions, m.distribution)},
      {"geometry", modelName(kGeometryTerms, m.geometry)},
      {"fresnel", modelName(kFresnelTerms, m.fresnel)},
      {"alpha", m.alpha},
      {"diffuse", array(m.diffuse)},
  };
  if (!m.name.empty()) json["name"] = m.name;
  if (m.energyCompensation) json["energy_compensation"] = true;
  if (m.anisotropy > 0.0) json["anisotropy"] = m.anisotropy, json["anisotropy_rotation"] = m.anisotropyRotation;
  if (m.clearcoat > 0.0) json["clearcoat"] = m.clearcoat, json["clearcoat_roughness"] = m.clearcoatRoughness;
  if (m.sheenColor != glm::dvec3(0.0))
    json["sheen_color"] = array(m.sheenColor), json["sheen_roughness"] = m.sheenRoughness;
  if (m.iridescence > 0.0) {
    json["iridescence"] = m.iridescence;
    json["iridescence_ior"] = m.iridescenceIor;
    json["iridescence_thickness"] = m.iridescenceThickness;
  }
  if (isTransmissive(m)) {
    json["transmission"] = m.transmission;
    if (m.thinWalled) json["thin_walled"] = true, json["thickness"] = m.thickness;
    if (std::isfinite(m.attenuationDistance)) {
      json["attenuation_color"] = array(m.attenuationColor);
      json["attenuation_distance"] = m.attenuationDistance;
    }
  }
  switch (m.fresnel) {
    case rules::f64::F_SCHLICK:
    case rules::f64::F_BLENDER_METALLIC:
      json["f0"] = array(m.f0);
      break;
    case rules::f64::F_DIELECTRIC:
      json["ior"] = array(m.eta);
      break;
    case rules::f64::F_CONDUCTOR:
      json["eta"] = array(m.eta);
      json["k"] = array(m.k);
      break;
  }
  return json;
}

}  // namespace facet::materials

#include "api/material.h"

#include "materials/parameter_table.h"

namespace facet::api {
namespace {

template <class T>
std::optional<T> engineValue(const std::optional<T>& value) {
  return value;
}
std::optional<bool> engineValue(bool value) { return value; }
std::optional<glm::dvec3> engineValue(const std::optional<v0::Vec3>& v) {
  if (!v) return std::nullopt;
  return glm::dvec3(v->x, v->y, v->z);
}

}  // namespace

materials::Material toEngineMaterial(const v0::Material& material, const std::string& where) {
  materials::MaterialSpec spec;
  spec.name = material.name;
  spec.preset = material.preset;
  spec.distribution = material.distribution;
  spec.geometry = material.geometry;
  spec.fresnel = material.fresnel;
  materials::forEachParameter([&](const auto& row) { spec.*row.spec = engineValue(material.*row.api); });
  return materials::buildMaterial(spec, [&](std::string_view field) { return where + "." + std::string(field); });
}

}  // namespace facet::api

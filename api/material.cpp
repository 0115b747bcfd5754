#include "api/material.h"

namespace facet::api {
namespace {

std::optional<glm::dvec3> engineVector(const std::optional<v0::Vec3>& v) {
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
  spec.alpha = material.alpha;
  spec.roughness = material.roughness;
  spec.f0 = engineVector(material.f0);
  spec.ior = engineVector(material.ior);
  spec.eta = engineVector(material.eta);
  spec.k = engineVector(material.k);
  spec.diffuse = engineVector(material.diffuse);
  spec.energyCompensation = material.energyCompensation;
  spec.transmission = material.transmission;
  spec.thinWalled = material.thinWalled;
  spec.thickness = material.thickness;
  spec.attenuationColor = engineVector(material.attenuationColor);
  spec.attenuationDistance = material.attenuationDistance;
  spec.anisotropy = material.anisotropy;
  spec.anisotropyRotation = material.anisotropyRotation;
  spec.clearcoat = material.clearcoat;
  spec.clearcoatRoughness = material.clearcoatRoughness;
  spec.sheenColor = engineVector(material.sheenColor);
  spec.sheenRoughness = material.sheenRoughness;
  spec.baseColor = engineVector(material.baseColor);
  spec.metallic = material.metallic;
  return materials::buildMaterial(spec, [&](std::string_view field) { return where + "." + std::string(field); });
}

}  // namespace facet::api

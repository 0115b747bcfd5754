// glTF's KHR_materials_ior and KHR_materials_specular as a dielectric's F(0),
// and KHR_materials_transmission and KHR_materials_volume as facet's
// transmissive materials (docs/gltf.md).
#include <glm/common.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "scenes/gltf_internal.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {

double member(const tinygltf::Value& value, const char* key, double fallback, const std::string& where,
              const GltfReader& reader) {
  if (!value.Has(key)) return fallback;
  const tinygltf::Value& x = value.Get(key);
  if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble())) reader.fail(where + "." + key, "must be a finite number");
  return x.GetNumberAsDouble();
}

std::optional<std::string> factorRule(double value, materials::BoundedParameter parameter) {
  return rangeRule(value, parameter.bounds.lo, parameter.bounds.hi);
}

const tinygltf::Value* extension(const tinygltf::Material& gltf, const char* name) {
  const auto found = gltf.extensions.find(name);
  return found == gltf.extensions.end() ? nullptr : &found->second;
}

namespace {

// KHR_materials_specular's factors over F(0) of the index `f0`: their
// dielectric_f0 is min(color, 1) × factor (times the textures per hit). Its
// F(90) would be specularFactor; facet's Schlick F keeps 1 (a warning
// below 1).
DielectricSpecular specularFactors(const tinygltf::Value& e, const std::string& at, const GltfReader& reader,
                                   glm::dvec3 f0) {
  const double factor = member(e, "specularFactor", 1.0, at, reader);
  if (const std::optional<std::string> rule = rangeRule(factor, 0.0, 1.0)) reader.fail(at + ".specularFactor", *rule);
  glm::dvec3 colour(1.0);
  if (e.Has("specularColorFactor")) {
    const tinygltf::Value& c = e.Get("specularColorFactor");
    if (!c.IsArray() || c.ArrayLen() != 3) reader.fail(at + ".specularColorFactor", "must be an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& x = c.Get(i);
      colour[i] = x.IsNumber() ? x.GetNumberAsDouble() : -1.0;
      if (!(colour[i] >= 0.0) || !std::isfinite(colour[i]))
        reader.fail(at + ".specularColorFactor", "every component must be a finite number >= 0");
    }
  }
  if (factor < 1.0)
    reader.warn(at + ".specularFactor", "below 1 scales F(0) only; F(90) stays 1 (facet's Schlick F has no F(90))");
  return {f0 * colour, factor};
}

}  // namespace

DielectricSpecular applyTransmission(const tinygltf::Material& gltf, const std::string& material,
                                     const GltfReader& reader, const glm::dvec3& base, double metallic,
                                     materials::Material& m) {
  const std::string at = material + ".extensions.";
  double ior = 1.5;
  const tinygltf::Value* iorExtension = extension(gltf, "KHR_materials_ior");
  if (iorExtension) {
    ior = member(*iorExtension, "ior", 1.5, at + "KHR_materials_ior", reader);
    if (!(ior >= 1.0 && ior <= materials::kMaxOpticalConstant))
      reader.fail(at + "KHR_materials_ior.ior",
                  "must be in [1, " + formatNumber(materials::kMaxOpticalConstant) + "], is " + formatNumber(ior));
  }
  // The dielectric's F(0) from its index, in place of 0.04 (= index 1.5).
  DielectricSpecular dielectric{glm::dvec3(std::pow((ior - 1) / (ior + 1), 2.0)), 1.0};
  const tinygltf::Value* specular = extension(gltf, "KHR_materials_specular");
  if (specular) dielectric = specularFactors(*specular, at + "KHR_materials_specular", reader, dielectric.color);
  if (iorExtension || specular) m.f0 = glm::mix(glm::min(dielectric.color, 1.0) * dielectric.factor, base, metallic);
  const tinygltf::Value* t = extension(gltf, "KHR_materials_transmission");
  if (!t) return dielectric;
  const std::string where = at + "KHR_materials_transmission";
  m.transmission = member(*t, "transmissionFactor", 0.0, where, reader);
  if (const std::optional<std::string> rule =
          factorRule(m.transmission, materials::bounded(&materials::MaterialSpec::transmission)))
    reader.fail(where + ".transmissionFactor", *rule);
  if (!materials::isTransmissive(m)) return dielectric;
  if (specular)
    reader.warn(at + "KHR_materials_specular",
                "is not applied to a transmissive material: its Fresnel is the dielectric's of its index");
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.eta = glm::dvec3(ior);
  m.thinWalled = true;  // glTF: without a volume, the surface is thin-walled
  const tinygltf::Value* v = extension(gltf, "KHR_materials_volume");
  if (!v) return dielectric;
  const std::string volume = at + "KHR_materials_volume";
  // thicknessTexture only helps a rasterizer guess the path inside; facet traces it.
  const double thickness = member(*v, "thicknessFactor", 0.0, volume, reader);
  if (!(thickness >= 0.0)) reader.fail(volume + ".thicknessFactor", "must be >= 0, is " + formatNumber(thickness));
  m.thinWalled = thickness == 0.0;
  m.attenuationDistance = member(*v, "attenuationDistance", std::numeric_limits<double>::infinity(), volume, reader);
  if (v->Has("attenuationDistance") && !(m.attenuationDistance > 0.0))
    reader.fail(volume + ".attenuationDistance", "must be > 0, is " + formatNumber(m.attenuationDistance));
  if (v->Has("attenuationColor")) {
    const tinygltf::Value& c = v->Get("attenuationColor");
    if (!c.IsArray() || c.ArrayLen() != 3) reader.fail(volume + ".attenuationColor", "must be an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& x = c.Get(i);
      const double value = x.IsNumber() ? x.GetNumberAsDouble() : -1.0;
      if (!(value >= 0.0 && value <= 1.0))
        reader.fail(volume + ".attenuationColor", "every component must be a number in [0, 1]");
      m.attenuationColor[i] = value;
    }
  }
  return dielectric;
}

}  // namespace facet::scene::detail

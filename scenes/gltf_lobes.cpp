// The glTF extensions that add a lobe to the base or shape its lobe:
// KHR_materials_clearcoat, KHR_materials_sheen and KHR_materials_anisotropy
// (docs/gltf.md).
#include <optional>
#include <utility>

#include "scenes/gltf_internal.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {

// KHR_materials_clearcoat's factors into `m` (docs/gltf.md, "Clear coat");
// its textures are not read, each with a warning saying what facet renders.
void applyClearcoat(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                    materials::Material& m) {
  const tinygltf::Value* c = extension(gltf, "KHR_materials_clearcoat");
  if (!c) return;
  const std::string at = material + ".extensions.KHR_materials_clearcoat";
  const double strength = member(*c, "clearcoatFactor", 0.0, at, reader);
  const double roughness = member(*c, "clearcoatRoughnessFactor", 0.0, at, reader);
  for (auto [field, value] :
       {std::pair{".clearcoatFactor", strength}, std::pair{".clearcoatRoughnessFactor", roughness}})
    if (const std::optional<std::string> rule = rangeRule(value, 0.0, 1.0)) reader.fail(at + field, *rule);
  const std::pair<const char*, const char*> kTextures[] = {
      {"clearcoatTexture", "is not read; the coat has clearcoatFactor everywhere"},
      {"clearcoatRoughnessTexture", "is not read; the coat has clearcoatRoughnessFactor everywhere"},
      {"clearcoatNormalTexture", "is not read; the coat follows the surface's normal, without a normal map"}};
  for (auto [texture, instead] : kTextures)
    if (c->Has(texture)) reader.warn(at + "." + texture, instead);
  if (strength > 0.0 && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it without its coat");
    return;
  }
  m.clearcoat = strength;
  m.clearcoatRoughness = roughness;
}

// KHR_materials_sheen's factors into `m` (docs/gltf.md, "Sheen"); its
// textures are not read, each with a warning saying what facet renders.
void applySheen(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                materials::Material& m) {
  const tinygltf::Value* s = extension(gltf, "KHR_materials_sheen");
  if (!s) return;
  const std::string at = material + ".extensions.KHR_materials_sheen";
  glm::dvec3 color(0.0);
  if (s->Has("sheenColorFactor")) {
    const tinygltf::Value& c = s->Get("sheenColorFactor");
    if (!c.IsArray() || c.ArrayLen() != 3) reader.fail(at + ".sheenColorFactor", "must be an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& x = c.Get(i);
      color[i] = x.IsNumber() ? x.GetNumberAsDouble() : -1.0;
      if (!(color[i] >= 0.0 && color[i] <= 1.0))
        reader.fail(at + ".sheenColorFactor", "every component must be a number in [0, 1]");
    }
  }
  const double roughness = member(*s, "sheenRoughnessFactor", 0.0, at, reader);
  if (const std::optional<std::string> rule = rangeRule(roughness, 0.0, 1.0))
    reader.fail(at + ".sheenRoughnessFactor", *rule);
  const std::pair<const char*, const char*> kTextures[] = {
      {"sheenColorTexture", "is not read; the sheen has sheenColorFactor everywhere"},
      {"sheenRoughnessTexture", "is not read; the sheen has sheenRoughnessFactor everywhere"}};
  for (auto [texture, instead] : kTextures)
    if (s->Has(texture)) reader.warn(at + "." + texture, instead);
  if (color != glm::dvec3(0.0) && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it without its sheen");
    return;
  }
  m.sheenColor = color;
  m.sheenRoughness = roughness;
}

// KHR_materials_anisotropy's factors into `m` (docs/gltf.md): its strength
// and rotation are facet's anisotropy and anisotropy_rotation, about the
// tangent glTF names, dP/du of the texture coordinates (docs/shading.md,
// "Anisotropy"). The direction texture is not read, with a warning.
void applyAnisotropy(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                     materials::Material& m) {
  const tinygltf::Value* a = extension(gltf, "KHR_materials_anisotropy");
  if (!a) return;
  const std::string at = material + ".extensions.KHR_materials_anisotropy";
  const double strength = member(*a, "anisotropyStrength", 0.0, at, reader);
  if (const std::optional<std::string> rule = rangeRule(strength, 0.0, 1.0))
    reader.fail(at + ".anisotropyStrength", *rule);
  const double rotation = member(*a, "anisotropyRotation", 0.0, at, reader);
  if (a->Has("anisotropyTexture"))
    reader.warn(at + ".anisotropyTexture",
                "is not read; the lobe is stretched along the tangent turned by anisotropyRotation, with "
                "anisotropyStrength everywhere");
  if (strength > 0.0 && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it isotropic");
    return;
  }
  m.anisotropy = strength;
  m.anisotropyRotation = rotation;
}

}  // namespace facet::scene::detail

// The glTF extensions that add a lobe to the base or shape its lobe:
// KHR_materials_clearcoat, KHR_materials_sheen, KHR_materials_iridescence
// and KHR_materials_anisotropy (docs/gltf.md), and the textures of every
// extension.
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "scenes/gltf_internal.h"

namespace facet::scene::detail {

// KHR_materials_clearcoat's factors into `m` (docs/gltf.md, "Clear coat");
// its textures are readLayerTextures'.
void applyClearcoat(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                    materials::Material& m) {
  const tinygltf::Value* c = extension(gltf, "KHR_materials_clearcoat");
  if (!c) return;
  const std::string at = material + ".extensions.KHR_materials_clearcoat";
  const double strength = member(*c, "clearcoatFactor", 0.0, at, reader);
  const double roughness = member(*c, "clearcoatRoughnessFactor", 0.0, at, reader);
  using materials::MaterialSpec, materials::bounded;
  if (const std::optional<std::string> rule = factorRule(strength, bounded(&MaterialSpec::clearcoat)))
    reader.fail(at + ".clearcoatFactor", *rule);
  if (const std::optional<std::string> rule = factorRule(roughness, bounded(&MaterialSpec::clearcoatRoughness)))
    reader.fail(at + ".clearcoatRoughnessFactor", *rule);
  if (strength > 0.0 && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it without its coat");
    return;
  }
  m.clearcoat = strength;
  m.clearcoatRoughness = roughness;
}

// KHR_materials_sheen's factors into `m` (docs/gltf.md, "Sheen"); its
// textures are readLayerTextures'.
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
  if (const std::optional<std::string> rule =
          factorRule(roughness, materials::bounded(&materials::MaterialSpec::sheenRoughness)))
    reader.fail(at + ".sheenRoughnessFactor", *rule);
  if (color != glm::dvec3(0.0) && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it without its sheen");
    return;
  }
  m.sheenColor = color;
  m.sheenRoughness = roughness;
}

// KHR_materials_iridescence's factors into `m` (docs/gltf.md,
// "Iridescence"): the factor, the film's index and its thickness the
// extension's maximum, where its thickness texture (readLayerTextures')
// does not place it between the minimum and the maximum.
void applyIridescence(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                      materials::Material& m) {
  const tinygltf::Value* i = extension(gltf, "KHR_materials_iridescence");
  if (!i) return;
  const std::string at = material + ".extensions.KHR_materials_iridescence";
  const double factor = member(*i, "iridescenceFactor", 0.0, at, reader);
  if (const std::optional<std::string> rule =
          factorRule(factor, materials::bounded(&materials::MaterialSpec::iridescence)))
    reader.fail(at + ".iridescenceFactor", *rule);
  const double ior = member(*i, "iridescenceIor", 1.3, at, reader);
  if (!(ior >= 1.0 && ior <= materials::kMaxOpticalConstant))
    reader.fail(at + ".iridescenceIor", "must be in [1, 1000], is " + formatNumber(ior));
  const double thinnest = member(*i, "iridescenceThicknessMinimum", 100.0, at, reader);
  const double thickest = member(*i, "iridescenceThicknessMaximum", 400.0, at, reader);
  for (const auto& [key, nm] :
       {std::pair{".iridescenceThicknessMinimum", thinnest}, std::pair{".iridescenceThicknessMaximum", thickest}})
    if (!(nm >= 0.0 && std::isfinite(nm)))
      reader.fail(at + key, "must be finite and >= 0 (nanometres), is " + formatNumber(nm));
  if (factor > 0.0 && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it without its thin film");
    return;
  }
  m.iridescence = factor;
  m.iridescenceIor = ior;
  m.iridescenceThickness = thickest;
}

// KHR_materials_anisotropy's factors into `m` (docs/gltf.md): its strength
// and rotation are facet's anisotropy and anisotropy_rotation, about the
// tangent glTF names, dP/du of the texture coordinates (docs/shading.md,
// "Anisotropy"); its direction texture is readLayerTextures'.
void applyAnisotropy(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                     materials::Material& m) {
  const tinygltf::Value* a = extension(gltf, "KHR_materials_anisotropy");
  if (!a) return;
  const std::string at = material + ".extensions.KHR_materials_anisotropy";
  const double strength = member(*a, "anisotropyStrength", 0.0, at, reader);
  if (const std::optional<std::string> rule =
          factorRule(strength, materials::bounded(&materials::MaterialSpec::anisotropy)))
    reader.fail(at + ".anisotropyStrength", *rule);
  const double rotation = member(*a, "anisotropyRotation", 0.0, at, reader);
  if (strength > 0.0 && materials::isTransmissive(m)) {
    reader.warn(at, "is not applied to a transmissive material: facet renders it isotropic");
    return;
  }
  m.anisotropy = strength;
  m.anisotropyRotation = rotation;
}

namespace {

// The texture info `key` of extension object `value` at field `at` (glTF
// 2.0, textureInfo: `index`, `texCoord`, its extensions), as a slot.
materials::TextureSlot extensionSlot(const tinygltf::Value& value, const char* key, TextureEncoding encoding,
                                     const std::string& at, const GltfReader& reader, TextureTable& textures) {
  if (!value.Has(key)) return {};
  const std::string where = at + "." + key;
  const tinygltf::Value& info = value.Get(key);
  if (!info.IsObject()) reader.fail(where, "must be a texture info object");
  const auto whole = [&](const char* member, int fallback) {
    if (!info.Has(member)) return fallback;
    const tinygltf::Value& x = info.Get(member);
    if (!x.IsInt() || x.GetNumberAsInt() < 0) reader.fail(where + "." + member, "must be a whole number >= 0");
    return x.GetNumberAsInt();
  };
  if (!info.Has("index")) reader.fail(where + ".index", "is required");
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions")) {
    const tinygltf::Value& e = info.Get("extensions");
    if (!e.IsObject()) reader.fail(where + ".extensions", "must be an object");
    for (const std::string& name : e.Keys()) extensions[name] = e.Get(name);
  }
  return textures.slot(extensions, whole("index", -1), whole("texCoord", 0), encoding, where);
}

}  // namespace

bool readLayerTextures(const tinygltf::Material& gltf, const materials::Material& m, const std::string& material,
                       const GltfReader& reader, TextureTable& textures, materials::MaterialTextures& t) {
  const auto at = [&](const char* name) { return material + ".extensions." + name; };
  if (const tinygltf::Value* c = extension(gltf, "KHR_materials_clearcoat")) {
    const std::string where = at("KHR_materials_clearcoat");
    t.clearcoatTexture = extensionSlot(*c, "clearcoatTexture", TextureEncoding::Linear, where, reader, textures);
    t.clearcoatRoughnessTexture =
        extensionSlot(*c, "clearcoatRoughnessTexture", TextureEncoding::Linear, where, reader, textures);
    t.clearcoatNormalTexture =
        extensionSlot(*c, "clearcoatNormalTexture", TextureEncoding::Linear, where, reader, textures);
    if (c->Has("clearcoatNormalTexture") && c->Get("clearcoatNormalTexture").Has("scale"))
      t.clearcoatNormalScale =
          member(c->Get("clearcoatNormalTexture"), "scale", 1.0, where + ".clearcoatNormalTexture", reader);
  }
  if (const tinygltf::Value* s = extension(gltf, "KHR_materials_sheen")) {
    const std::string where = at("KHR_materials_sheen");
    t.sheenColorTexture = extensionSlot(*s, "sheenColorTexture", TextureEncoding::Srgb, where, reader, textures);
    const materials::TextureSlot roughness =
        extensionSlot(*s, "sheenRoughnessTexture", TextureEncoding::Linear, where, reader, textures);
    // Only a sheen that is there, of a roughness above 0, varies per hit.
    if (m.sheenColor != glm::dvec3(0.0) && m.sheenRoughness > 0.0) {
      t.sheenRoughnessTexture = roughness;
      t.sheenRoughness = m.sheenRoughness;
    }
  }
  if (const tinygltf::Value* a = extension(gltf, "KHR_materials_anisotropy"))
    t.anisotropyTexture = extensionSlot(*a, "anisotropyTexture", TextureEncoding::Linear,
                                        at("KHR_materials_anisotropy"), reader, textures);
  if (const tinygltf::Value* x = extension(gltf, "KHR_materials_transmission"))
    t.transmissionTexture = extensionSlot(*x, "transmissionTexture", TextureEncoding::Linear,
                                          at("KHR_materials_transmission"), reader, textures);
  if (const tinygltf::Value* s = extension(gltf, "KHR_materials_specular")) {
    const std::string where = at("KHR_materials_specular");
    t.specularTexture = extensionSlot(*s, "specularTexture", TextureEncoding::Linear, where, reader, textures);
    t.specularColorTexture = extensionSlot(*s, "specularColorTexture", TextureEncoding::Srgb, where, reader, textures);
  }
  if (const tinygltf::Value* i = extension(gltf, "KHR_materials_iridescence")) {
    const std::string where = at("KHR_materials_iridescence");
    t.iridescenceTexture = extensionSlot(*i, "iridescenceTexture", TextureEncoding::Linear, where, reader, textures);
    const materials::TextureSlot thickness =
        extensionSlot(*i, "iridescenceThicknessTexture", TextureEncoding::Linear, where, reader, textures);
    // Between a minimum and a maximum that differ, of a film that is there.
    t.iridescenceThicknessMinimum = member(*i, "iridescenceThicknessMinimum", 100.0, where, reader);
    if (m.iridescence > 0.0 && t.iridescenceThicknessMinimum != m.iridescenceThickness)
      t.iridescenceThicknessTexture = thickness;
  }
  for (const materials::TextureSlot* slot :
       {&t.clearcoatTexture, &t.clearcoatRoughnessTexture, &t.clearcoatNormalTexture, &t.sheenColorTexture,
        &t.sheenRoughnessTexture, &t.anisotropyTexture, &t.transmissionTexture, &t.specularTexture,
        &t.specularColorTexture, &t.iridescenceTexture, &t.iridescenceThicknessTexture})
    if (slot->texture >= 0) return true;
  return false;
}

}  // namespace facet::scene::detail

// glTF materials (metallic-roughness) and the textures and samplers they use.
#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <optional>

#include "scenes/gltf_internal.h"
#include "scenes/scene_file.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {
namespace {

// The glTF sampler's codes (OpenGL's enums) as rules/texture/texture_sampling.h's.
TextureSampler toSampler(const tinygltf::Sampler& gltf, const std::string& where, const GltfReader& reader) {
  namespace t = rules::f64;
  TextureSampler sampler;
  auto wrap = [&](int mode, const char* field) {
    switch (mode) {
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return t::FACET_WRAP_REPEAT;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return t::FACET_WRAP_MIRRORED_REPEAT;
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return t::FACET_WRAP_CLAMP_TO_EDGE;
    }
    reader.fail(where + field, "unknown wrap mode " + std::to_string(mode) + " (expected 10497, 33648 or 33071)");
  };
  sampler.wrapS = wrap(gltf.wrapS, ".wrapS");
  sampler.wrapT = wrap(gltf.wrapT, ".wrapT");
  if (gltf.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST)
    sampler.magFilter = t::FACET_FILTER_NEAREST;
  else if (gltf.magFilter != -1 && gltf.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
    reader.fail(where + ".magFilter", "unknown filter " + std::to_string(gltf.magFilter) + " (expected 9728 or 9729)");
  // minFilter: the filter within a level and the mip mode, by OpenGL's codes.
  struct MinFilter {
    int code;
    std::uint32_t texelFilter, mipMode;
  };
  const MinFilter minFilters[] = {
      {TINYGLTF_TEXTURE_FILTER_NEAREST, t::FACET_FILTER_NEAREST, t::FACET_MIP_NONE},
      {TINYGLTF_TEXTURE_FILTER_LINEAR, t::FACET_FILTER_LINEAR, t::FACET_MIP_NONE},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST, t::FACET_FILTER_NEAREST, t::FACET_MIP_NEAREST},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST, t::FACET_FILTER_LINEAR, t::FACET_MIP_NEAREST},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR, t::FACET_FILTER_NEAREST, t::FACET_MIP_LINEAR},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR, t::FACET_FILTER_LINEAR, t::FACET_MIP_LINEAR}};
  if (gltf.minFilter != -1) {
    const auto found = std::find_if(std::begin(minFilters), std::end(minFilters),
                                    [&](const MinFilter& f) { return f.code == gltf.minFilter; });
    if (found == std::end(minFilters))
      reader.fail(where + ".minFilter",
                  "unknown filter " + std::to_string(gltf.minFilter) + " (expected 9728, 9729 or 9984 to 9987)");
    sampler.minFilter = found->texelFilter;
    sampler.mipMode = found->mipMode;
  }
  return sampler;
}

}  // namespace

materials::TextureSlot TextureTable::slot(const tinygltf::ExtensionMap& extensions, int index, int texCoord,
                                          TextureEncoding encoding, const std::string& where, const char* withoutIt) {
  materials::TextureSlot slot;
  if (index == -1) return slot;  // tinygltf's "no texture"; any other negative index is the file's error
  if (index < 0 || std::size_t(index) >= model_.textures.size())
    reader_.fail(where + ".index", "texture index " + std::to_string(index) + " out of range (the file has " +
                                       std::to_string(model_.textures.size()) + " textures)");
  if (auto found = extensions.find("KHR_texture_transform"); found != extensions.end()) {
    const tinygltf::Value& transform = found->second;
    const std::string at = where + ".extensions.KHR_texture_transform";
    slot.offset = pair(transform, "offset", at, glm::dvec2(0.0));
    slot.scale = pair(transform, "scale", at, glm::dvec2(1.0));
    if (transform.Has("rotation")) slot.rotation = number(transform.Get("rotation"), at + ".rotation");
    if (transform.Has("texCoord")) texCoord = int(number(transform.Get("texCoord"), at + ".texCoord"));
  }
  if (texCoord > 1 && !withoutIt)
    reader_.fail(where + ".texCoord",
                 "only TEXCOORD_0 and TEXCOORD_1 are read, not TEXCOORD_" + std::to_string(texCoord));
  if (texCoord > 1) {
    reader_.warn(where + ".texCoord", "only TEXCOORD_0 and TEXCOORD_1 are read, so this slot on TEXCOORD_" +
                                          std::to_string(texCoord) + " is dropped: " + withoutIt);
    return {};
  }
  slot.texCoord = texCoord;
  // glTF textures that pair the same image with the same sampler are one
  // texture: converted, filtered into mip levels and uploaded once.
  const tinygltf::Texture& gltf = model_.textures[std::size_t(index)];
  auto [cached, fresh] = cache_.try_emplace({gltf.source, gltf.sampler, encoding}, int(textures_.size()));
  if (fresh) textures_.push_back(convert(index, encoding));
  slot.texture = cached->second;
  return slot;
}

double TextureTable::number(const tinygltf::Value& value, const std::string& where) const {
  if (!value.IsNumber()) reader_.fail(where, "must be a number");
  const double x = value.GetNumberAsDouble();
  if (!std::isfinite(x)) reader_.fail(where, "must be finite");
  return x;
}

glm::dvec2 TextureTable::pair(const tinygltf::Value& transform, const char* key, const std::string& at,
                              glm::dvec2 fallback) const {
  if (!transform.Has(key)) return fallback;
  const tinygltf::Value& value = transform.Get(key);
  const std::string where = at + "." + key;
  if (!value.IsArray() || value.ArrayLen() != 2) reader_.fail(where, "must be an array of 2 numbers");
  return {number(value.Get(0), where + "[0]"), number(value.Get(1), where + "[1]")};
}

Texture TextureTable::convert(int index, TextureEncoding encoding) const {
  const tinygltf::Texture& gltf = model_.textures[std::size_t(index)];
  const std::string where = "textures[" + std::to_string(index) + "]";
  if (gltf.source < 0 || std::size_t(gltf.source) >= model_.images.size())
    reader_.fail(where + ".source", "image index " + std::to_string(gltf.source) + " out of range (the file has " +
                                        std::to_string(model_.images.size()) + " images)");
  TextureSampler sampler;
  if (gltf.sampler >= 0) {
    if (std::size_t(gltf.sampler) >= model_.samplers.size())
      reader_.fail(where + ".sampler", "sampler index " + std::to_string(gltf.sampler) + " out of range");
    sampler = toSampler(model_.samplers[std::size_t(gltf.sampler)], "samplers[" + std::to_string(gltf.sampler) + "]",
                        reader_);
  }
  const tinygltf::Image& image = model_.images[std::size_t(gltf.source)];
  const std::string imageWhere = "images[" + std::to_string(gltf.source) + "]";
  const std::string name = image.uri.empty() ? imageWhere : image.uri;
  // tinygltf keeps an external image it cannot open as its uri alone.
  if (image.image.empty()) reader_.fail(imageWhere, "cannot read the image '" + name + "' (no such file)");
  if (image.width > kMaxTextureSize || image.height > kMaxTextureSize)
    reader_.fail(imageWhere, "an image must be at most " + std::to_string(kMaxTextureSize) + " x " +
                                 std::to_string(kMaxTextureSize) + ", is " + std::to_string(image.width) + " x " +
                                 std::to_string(image.height));
  const std::size_t values = std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.component);
  const std::size_t bytes = image.bits == 16 ? 2 : 1;
  if (image.bits != 8 && image.bits != 16) reader_.fail(imageWhere, "only 8- and 16-bit images are read");
  if (image.image.size() != values * bytes) reader_.fail(imageWhere, "the decoded size differs from the image's");
  std::vector<float> channels(values);
  for (std::size_t i = 0; i < values; ++i) {
    std::uint16_t wide = 0;
    if (bytes == 2) std::memcpy(&wide, &image.image[2 * i], 2);
    channels[i] = bytes == 2 ? float(wide) / 65535.0f : float(image.image[i]) / 255.0f;
  }
  return makeTexture(name, image.width, image.height, image.component, channels, encoding, sampler);
}

namespace {

// KHR_materials_unlit: the surface shows its base colour (factor, texture
// and vertex colour) whatever lights it, as an emitter of that colour that
// reflects nothing: no diffuse and no interface (a dielectric of index 1,
// whose Fresnel is 0 at every angle, F90 included). The specification's
// other lighting properties are its fallbacks for viewers without the
// extension.
materials::Material unlitMaterial(const std::string& name, const glm::dvec3& base,
                                  const materials::TextureSlot& baseColorTexture, bool vertexColours) {
  materials::Material m = defaultMaterial();
  m.name = name;
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.eta = glm::dvec3(1.0);
  m.diffuse = glm::dvec3(0.0);
  m.emission = base;
  if (baseColorTexture.texture >= 0 || vertexColours) {
    materials::MaterialTextures t;
    t.baseColor = base;
    t.baseColorTexture = baseColorTexture;
    t.metallic = 1.0;  // per hit: no diffuse; F(0) is unread under the index-1 Fresnel
    t.unlit = true;
    m.textures = t;
  }
  return m;
}

}  // namespace

materials::Material toMaterial(const tinygltf::Material& gltf, std::size_t index, const GltfReader& reader,
                               TextureTable& textures, bool vertexColours) {
  const auto& pbr = gltf.pbrMetallicRoughness;
  const std::string material = "materials[" + std::to_string(index) + "]";
  const std::string where = material + ".pbrMetallicRoughness";
  for (double c : pbr.baseColorFactor)
    if (!(c >= 0.0 && c <= 1.0))
      reader.fail(where + ".baseColorFactor", "every component must be in [0, 1], is " + formatNumber(c));
  glm::dvec3 base(1.0);
  if (pbr.baseColorFactor.size() >= 3) base = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
  using materials::MaterialSpec, materials::bounded;
  if (const std::optional<std::string> rule = factorRule(pbr.metallicFactor, bounded(&MaterialSpec::metallic)))
    reader.fail(where + ".metallicFactor", *rule);
  if (const std::optional<std::string> rule = factorRule(pbr.roughnessFactor, bounded(&MaterialSpec::roughness)))
    reader.fail(where + ".roughnessFactor", *rule);
  const double metallic = pbr.metallicFactor;
  const double roughness = pbr.roughnessFactor;
  const std::string name = gltf.name.empty() ? "material " + std::to_string(index) : gltf.name;
  if (extension(gltf, "KHR_materials_unlit")) {
    const auto& b = pbr.baseColorTexture;
    return unlitMaterial(
        name, base,
        textures.slot(b.extensions, b.index, b.texCoord, TextureEncoding::Srgb, where + ".baseColorTexture"),
        vertexColours);
  }
  materials::Material m = defaultMaterial();
  m.name = name;
  m.diffuse = base * (1.0 - metallic);
  m.f0 = glm::mix(glm::dvec3(0.04), base, metallic);
  m.alpha = roughness * roughness;
  const DielectricSpecular dielectric = applyTransmission(gltf, material, reader, base, metallic, m);
  applyClearcoat(gltf, material, reader, m);
  applySheen(gltf, material, reader, m);
  applyIridescence(gltf, material, reader, m);
  applyAnisotropy(gltf, material, reader, m);
  for (double c : gltf.emissiveFactor)
    if (!(c >= 0.0 && c <= 1.0))
      reader.fail(material + ".emissiveFactor", "every component must be in [0, 1], is " + formatNumber(c));
  if (gltf.emissiveFactor.size() == 3)
    m.emission = {gltf.emissiveFactor[0], gltf.emissiveFactor[1], gltf.emissiveFactor[2]};
  // KHR_materials_emissive_strength: the one way past the factor's cap of 1.
  if (const tinygltf::Value* e = extension(gltf, "KHR_materials_emissive_strength")) {
    const std::string at = material + ".extensions.KHR_materials_emissive_strength";
    const double strength = member(*e, "emissiveStrength", 1.0, at, reader);
    if (!(strength >= 0.0)) reader.fail(at + ".emissiveStrength", "must be >= 0, is " + formatNumber(strength));
    m.emission *= strength;
    if (const std::optional<std::string> rule = radianceRule(m.emission))
      reader.fail(at + ".emissiveStrength", "emissiveFactor times emissiveStrength " + *rule);
  }

  materials::MaterialTextures t;
  t.baseColor = base;
  t.metallic = metallic;
  t.roughness = roughness;
  t.specularColor = dielectric.color;
  t.specular = dielectric.factor;
  const auto& b = pbr.baseColorTexture;
  t.baseColorTexture =
      textures.slot(b.extensions, b.index, b.texCoord, TextureEncoding::Srgb, where + ".baseColorTexture");
  const auto& mr = pbr.metallicRoughnessTexture;
  t.metallicRoughnessTexture =
      textures.slot(mr.extensions, mr.index, mr.texCoord, TextureEncoding::Linear, where + ".metallicRoughnessTexture");
  const auto& n = gltf.normalTexture;
  t.normalTexture =
      textures.slot(n.extensions, n.index, n.texCoord, TextureEncoding::Linear, material + ".normalTexture");
  t.normalScale = n.scale;
  const auto& o = gltf.occlusionTexture;
  t.occlusionTexture = textures.slot(o.extensions, o.index, o.texCoord, TextureEncoding::Linear,
                                     material + ".occlusionTexture", "the environment lights the surface unoccluded");
  if (const std::optional<std::string> rule = rangeRule(o.strength, 0.0, 1.0))
    reader.fail(material + ".occlusionTexture.strength", *rule);
  t.occlusionStrength = o.strength;
  const auto& e = gltf.emissiveTexture;
  t.emissiveTexture =
      textures.slot(e.extensions, e.index, e.texCoord, TextureEncoding::Srgb, material + ".emissiveTexture");
  const bool layered = readLayerTextures(gltf, m, material, reader, textures, t);
  for (const materials::TextureSlot* s :
       {&t.baseColorTexture, &t.metallicRoughnessTexture, &t.normalTexture, &t.occlusionTexture, &t.emissiveTexture})
    if (s->texture >= 0) m.textures = t;
  // A transmissive material's base colour tints what it transmits and its
  // metallic mixes a metal over it, per hit (docs/gltf.md).
  if (vertexColours || layered || materials::isTransmissive(m)) m.textures = t;
  return m;
}

GltfCutout readCutout(const tinygltf::Material& gltf, std::size_t index, const GltfReader& reader) {
  const std::string material = "materials[" + std::to_string(index) + "]";
  GltfCutout cutout;
  if (gltf.pbrMetallicRoughness.baseColorFactor.size() == 4)
    cutout.factor = gltf.pbrMetallicRoughness.baseColorFactor[3];
  if (gltf.alphaMode == "OPAQUE") return cutout;
  if (gltf.alphaMode == "BLEND") {
    cutout.mode = AlphaMode::Blend;
    return cutout;
  }
  if (gltf.alphaMode != "MASK")
    reader.fail(material + ".alphaMode", "must be OPAQUE, MASK or BLEND, is \"" + gltf.alphaMode + "\"");
  // glTF 2.0, 5.19: at least 0; 0 keeps every hit, as OPAQUE does.
  if (!(gltf.alphaCutoff >= 0.0 && std::isfinite(gltf.alphaCutoff)))
    reader.fail(material + ".alphaCutoff", "must be a number of at least 0, is " + formatNumber(gltf.alphaCutoff));
  cutout.cutoff = gltf.alphaCutoff;
  if (cutout.cutoff > 0.0) cutout.mode = AlphaMode::Mask;
  return cutout;
}

}  // namespace facet::scene::detail

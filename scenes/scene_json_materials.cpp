// Materials of facet's JSON scenes and material files: the fields, the
// files an entry names or extends, and the textures they read
// (docs/scene-format.md, "Materials" and "Material files").
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <vector>

#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/json_field.h"
#include "scenes/json_overrides.h"
#include "scenes/scene_file.h"
#include "scenes/texture.h"

namespace facet::scene {
namespace detail {
namespace {

constexpr const char* kTextureKeys[] = {"diffuse_texture", "f0_texture", "roughness_texture"};
// Files that extend files are read by recursion: the bound keeps a chain of
// any length within the stack (docs/reliability.md, "Limits").
constexpr std::size_t kDeepestExtends = 64;

// A texture field: an image file relative to the scene file, or an object
// of the image and its sampling.
Texture readTexture(const Field& f, const std::filesystem::path& sceneFile, bool roughness) {
  const bool detailed = f.value().is_object();
  if (detailed) {
    f.object({"image", "wrap", "filter"});
    if (!f.has("image")) f.fail("a texture needs an image (a PNG or JPEG file, relative to the scene file)");
  } else if (!f.value().is_string()) {
    f.fail("expected an image file name or an object with image, wrap and filter");
  }
  const Field image = detailed ? f["image"] : f;
  TextureSampler sampler;
  if (detailed && f.has("wrap"))
    sampler.wrapS = sampler.wrapT = f["wrap"].choice<std::uint32_t>({{"repeat", rules::f64::FACET_WRAP_REPEAT},
                                                                     {"mirror", rules::f64::FACET_WRAP_MIRRORED_REPEAT},
                                                                     {"clamp", rules::f64::FACET_WRAP_CLAMP_TO_EDGE}});
  if (detailed && f.has("filter") && f["filter"].choice<bool>({{"linear", false}, {"nearest", true}})) {
    sampler.magFilter = sampler.minFilter = rules::f64::FACET_FILTER_NEAREST;
    sampler.mipMode = rules::f64::FACET_MIP_NEAREST;
  }
  const std::filesystem::path file = sceneFile.parent_path() / image.string();
  if (const std::optional<std::string> problem = inputFileProblem(file)) image.fail(*problem + ": " + file.string());
  try {
    return roughness ? loadRoughnessTexture(file, sampler) : loadColorTexture(file, sampler);
  } catch (const InputError& e) {
    image.fail(e.what());
  }
}

// A material's texture fields, carried by glTF's metallic-roughness mapping
// that both backends evaluate (docs/scene-format.md): metallic 0 gives
// c_diff = base colour and F(0) = 0.04, metallic 1 gives F(0) = base colour
// and no c_diff. A colour factor the user left out is 1 under its texture.
void readMaterialTextures(const Field& f, const materials::MaterialSpec& spec, materials::Material& m,
                          const std::filesystem::path& sceneFile, std::vector<Texture>& textures) {
  const bool diffuseMap = f.has("diffuse_texture"), f0Map = f.has("f0_texture"),
             roughnessMap = f.has("roughness_texture");
  if (!diffuseMap && !f0Map && !roughnessMap) return;
  namespace m64 = rules::f64;
  const bool readsF0 = m.fresnel == m64::F_SCHLICK || m.fresnel == m64::F_BLENDER_METALLIC;
  if (f0Map && !readsF0) f["f0_texture"].fail("needs a fresnel that reads f0 (schlick or blender-metallic)");
  const bool dielectric = !f0Map && (!readsF0 || m.f0 == glm::dvec3(0.04));
  const bool metal = !diffuseMap && m.diffuse == glm::dvec3(0.0);
  if (diffuseMap && !dielectric)
    f["diffuse_texture"].fail(f0Map ? "cannot be combined with f0_texture"
                                    : "needs f0 0.04 (textures follow glTF's metallic-roughness model)");
  if (f0Map && !metal)
    f["f0_texture"].fail(diffuseMap ? "cannot be combined with diffuse_texture"
                                    : "needs diffuse 0 (textures follow glTF's metallic-roughness model)");
  if (!dielectric && !metal)
    f["roughness_texture"].fail("needs diffuse 0 or f0 0.04 (textures follow glTF's metallic-roughness model)");

  materials::MaterialTextures t;
  t.metallic = dielectric ? 0.0 : 1.0;
  const bool f0Given = spec.f0 || spec.preset;
  t.baseColor = dielectric ? (diffuseMap && !spec.diffuse ? glm::dvec3(1.0) : m.diffuse)
                           : (f0Map && !f0Given ? glm::dvec3(1.0) : m.f0);
  t.roughness = std::sqrt(m.alpha);
  auto slot = [&](const char* key, bool roughness) {
    materials::TextureSlot s;
    s.texture = int(textures.size());
    textures.push_back(readTexture(f[key], sceneFile, roughness));
    return s;
  };
  if (diffuseMap) t.baseColorTexture = slot("diffuse_texture", false);
  if (f0Map) t.baseColorTexture = slot("f0_texture", false);
  if (roughnessMap) t.metallicRoughnessTexture = slot("roughness_texture", true);
  m.textures = t;
}

// A material's fields without its textures, validated; errors name the
// field in `f`'s file.
materials::Material plainMaterial(const Field& f, const json& plain, materials::MaterialSpec& spec) {
  const std::string& where = f.path();
  try {
    spec = materials::materialSpecFromJson(plain, where.empty() ? "material" : where);
    return materials::buildMaterial(spec, [&](std::string_view field) {
      return where.empty() ? std::string(field) : where + "." + std::string(field);
    });
  } catch (const std::invalid_argument& e) {
    // "<field>: <rule>" split, so that an error in a field --set gave names the override.
    const std::string text = e.what();
    const std::size_t colon = text.find(": ");
    throw InputError(f.source(), 0, text.substr(0, colon), colon == std::string::npos ? "" : text.substr(colon + 2));
  }
}

std::vector<std::filesystem::path>::const_iterator find(const std::vector<std::filesystem::path>& chain,
                                                        const std::filesystem::path& file) {
  return std::find(chain.begin(), chain.end(), file);
}

// A file's texture images, relative to the file, as paths that no longer
// depend on where the file is.
void anchorTextures(json& material, const std::filesystem::path& file) {
  for (const char* key : kTextureKeys) {
    if (!material.contains(key)) continue;
    json& texture = material[key];
    json& image = texture.is_object() && texture.contains("image") ? texture["image"] : texture;
    if (image.is_string()) image = (file.parent_path() / image.get<std::string>()).string();
  }
}

json resolvedMaterial(const Field& f, const std::filesystem::path& relativeTo,
                      std::vector<std::filesystem::path>& chain);

// A material file, the files it extends merged in, checked as a material of
// its own so that its errors name it.
json materialFile(const Field& reference, const std::filesystem::path& relativeTo,
                  std::vector<std::filesystem::path>& chain) {
  const std::string name = reference.string();
  if (!namesMaterialFile(name)) reference.fail("a material file's name ends in .json");
  const std::filesystem::path file = relativeTo.parent_path() / name;
  noteInputFile(file);
  if (const std::optional<std::string> problem = inputFileProblem(file))
    reference.fail(*problem + ": " + file.string());
  std::error_code error;
  std::filesystem::path key = std::filesystem::weakly_canonical(file, error);
  if (error) key = file;
  if (find(chain, key) != chain.end()) {
    std::string cycle;
    for (auto at = find(chain, key); at != chain.end(); ++at) cycle += at->filename().string() + " -> ";
    reference.fail("material files extend each other in a cycle: " + cycle + key.filename().string());
  }
  if (chain.size() >= kDeepestExtends)
    reference.fail("material files extend each other more than " + std::to_string(kDeepestExtends) +
                   " deep, from " + chain.front().filename().string());
  const std::string source = file.string();
  std::ifstream in(file);
  json document;
  try {
    document = json::parse(in);
  } catch (const json::exception& e) {  // syntax errors, and numbers beyond double's range
    throw InputError(source, 0, "not valid JSON", e.what());
  }
  const Field root(document, "", source);
  if (!document.is_object()) root.fail("expected an object of material fields");
  chain.push_back(key);
  json material = resolvedMaterial(root, file, chain);
  chain.pop_back();
  json plain = material;
  for (const char* texture : kTextureKeys) plain.erase(texture);
  if (material.contains("roughness_texture") && !plain.contains("roughness") && !plain.contains("alpha"))
    plain["roughness"] = 1.0;
  materials::MaterialSpec spec;
  plainMaterial(Field(material, "", source), plain, spec);
  anchorTextures(material, file);
  return material;
}

// The fields of a material entry with every file it names or extends
// merged in, its own fields over the file's.
json resolvedMaterial(const Field& f, const std::filesystem::path& relativeTo,
                      std::vector<std::filesystem::path>& chain) {
  if (f.value().is_string()) {
    if (!namesMaterialFile(f.string()))
      f.fail("expected an object of material fields, or a material file (a name ending in .json)");
    return materialFile(f, relativeTo, chain);
  }
  if (!f.value().is_object()) f.fail("expected an object of material fields, or a material file (.json)");
  if (!f.has("extends")) return f.value();
  json own = f.value();
  own.erase("extends");
  json material = materialFile(f["extends"], relativeTo, chain);
  // The entry's alpha or roughness replaces the file's, whichever it gave.
  if (own.contains("alpha") || own.contains("roughness")) material.erase("alpha"), material.erase("roughness");
  material.update(own);
  return material;
}

}  // namespace

bool namesMaterialFile(std::string_view text) {
  if (text.size() < 5) return false;
  std::string extension(text.substr(text.size() - 5));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".json";
}

materials::Material readMaterial(const Field& f, const std::filesystem::path& relativeTo,
                                 std::vector<Texture>& textures) {
  std::vector<std::filesystem::path> chain;
  const json resolved = resolvedMaterial(f, relativeTo, chain);
  // A file named alone is its own entry: its errors name it.
  const bool file = f.value().is_string();
  const std::string fileSource = file ? (relativeTo.parent_path() / f.string()).string() : "";
  const Field r(resolved, file ? "" : f.path(), file ? fileSource : f.source());
  json plain = resolved;
  for (const char* key : kTextureKeys) plain.erase(key);
  // A roughness texture alone gives the roughness, as read.
  if (r.has("roughness_texture") && !plain.contains("roughness") && !plain.contains("alpha")) plain["roughness"] = 1.0;
  materials::MaterialSpec spec;
  materials::Material m = plainMaterial(r, plain, spec);
  readMaterialTextures(r, spec, m, relativeTo, textures);
  return m;
}

void expandMaterialFiles(json& document, std::span<const JsonOverride> overrides) {
  auto expand = [&](json& entry, const std::string& path) {
    const bool reached = std::any_of(overrides.begin(), overrides.end(), [&](const JsonOverride& o) {
      return o.path.size() > path.size() + 1 && o.path.compare(0, path.size() + 1, path + ".") == 0;
    });
    if (reached && entry.is_string() && namesMaterialFile(entry.get<std::string>())) entry = json{{"extends", entry}};
  };
  if (!document.is_object()) return;
  if (document.contains("materials") && document["materials"].is_object())
    for (auto& item : document["materials"].items()) expand(item.value(), "materials." + item.key());
  if (document.contains("objects") && document["objects"].is_array())
    for (std::size_t i = 0; i < document["objects"].size(); ++i)
      if (json& object = document["objects"][i]; object.is_object() && object.contains("material"))
        expand(object["material"], "objects[" + std::to_string(i) + "].material");
}

}  // namespace detail

materials::Material loadMaterialReference(const std::string& reference, std::vector<Texture>& textures) {
  const std::string source = "--material";
  if (!detail::namesMaterialFile(reference)) {
    const detail::json preset = {{"preset", reference}, {"roughness", std::sqrt(defaultMaterial().alpha)}};
    materials::Material m = detail::readMaterial(detail::Field(preset, "", source), "", textures);
    m.name = reference;
    return m;
  }
  const detail::json file = reference;
  materials::Material m =
      detail::readMaterial(detail::Field(file, reference, source), std::filesystem::current_path() / "", textures);
  m.name = std::filesystem::path(reference).stem().string();
  return m;
}

}  // namespace facet::scene

// What facet reads of a glTF file: the extensions it implements, and a
// warning for each extension and core feature it renders otherwise than the
// file says (docs/gltf.md lists both).
#include <algorithm>
#include <iterator>
#include <set>
#include <string_view>

#include "scenes/gltf_internal.h"

namespace facet::scene::detail {
namespace {

// The extensions facet implements; the one list the loader and its messages read.
constexpr std::string_view kImplemented[] = {
    "KHR_lights_punctual",        "KHR_materials_anisotropy",
    "KHR_materials_clearcoat",    "KHR_materials_emissive_strength",
    "KHR_materials_ior",          "KHR_materials_iridescence",
    "KHR_materials_sheen",        "KHR_materials_specular",
    "KHR_materials_transmission", "KHR_materials_unlit",
    "KHR_materials_variants",     "KHR_materials_volume",
    "KHR_texture_transform",
};

// What facet renders in place of an extension it ignores.
struct Fallback {
  std::string_view extension, instead;
};
constexpr Fallback kFallbacks[] = {
    {"KHR_materials_diffuse_transmission", "the base, opaque"},
    {"KHR_materials_dispersion", "one index of refraction for every wavelength"},
    {"KHR_materials_pbrSpecularGlossiness", "the material's metallic-roughness parameters"},
    {"KHR_texture_basisu", "each texture's core image (an error where it has none)"},
    {"EXT_texture_webp", "each texture's core image (an error where it has none)"},
    {"EXT_texture_avif", "each texture's core image (an error where it has none)"},
    {"KHR_draco_mesh_compression", "the uncompressed accessors (an error where there are none)"},
    {"EXT_meshopt_compression", "the uncompressed buffer views (an error where there are none)"},
    {"KHR_mesh_quantization", "float attributes only (integer ones are errors naming the accessor)"},
    {"EXT_mesh_gpu_instancing", "each node's mesh once, at the node, without its instances"},
    {"KHR_animation_pointer", "the scene without animation"},
};

bool implemented(const std::string& extension) {
  return std::find(std::begin(kImplemented), std::end(kImplemented), extension) != std::end(kImplemented);
}

std::string implementedList() {
  std::string list;
  for (std::string_view e : kImplemented) list.append(list.empty() ? "" : ", ").append(e);
  return list;
}

std::string ignoredExtension(const std::string& extension) {
  const auto found = std::find_if(std::begin(kFallbacks), std::end(kFallbacks),
                                  [&](const Fallback& f) { return f.extension == extension; });
  return "extension " + extension + " is not read; facet renders " +
         (found == std::end(kFallbacks) ? std::string("the file as if it were absent") : std::string(found->instead));
}

// The extensions on the parts of `model` that carry them, with where each is
// first seen, for a file that uses one without listing it in extensionsUsed.
void collectExtensions(const tinygltf::Model& model, std::vector<std::pair<std::string, std::string>>& seen) {
  const auto add = [&](const tinygltf::ExtensionMap& extensions, const std::string& where) {
    for (const auto& entry : extensions) seen.push_back({entry.first, where + ".extensions." + entry.first});
  };
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const std::string at = "materials[" + std::to_string(i) + "]";
    add(m.extensions, at);
    add(m.pbrMetallicRoughness.baseColorTexture.extensions, at + ".pbrMetallicRoughness.baseColorTexture");
    add(m.pbrMetallicRoughness.metallicRoughnessTexture.extensions,
        at + ".pbrMetallicRoughness.metallicRoughnessTexture");
    add(m.normalTexture.extensions, at + ".normalTexture");
    add(m.occlusionTexture.extensions, at + ".occlusionTexture");
    add(m.emissiveTexture.extensions, at + ".emissiveTexture");
  }
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    add(model.nodes[i].extensions, "nodes[" + std::to_string(i) + "]");
  for (std::size_t i = 0; i < model.meshes.size(); ++i)
    for (std::size_t p = 0; p < model.meshes[i].primitives.size(); ++p)
      add(model.meshes[i].primitives[p].extensions,
          "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(p) + "]");
  for (std::size_t i = 0; i < model.textures.size(); ++i)
    add(model.textures[i].extensions, "textures[" + std::to_string(i) + "]");
  add(model.extensions, "");
}

}  // namespace

void checkExtensions(const tinygltf::Model& model, const GltfReader& reader) {
  for (const std::string& extension : model.extensionsRequired)
    if (!implemented(extension))
      reader.fail("extensionsRequired", "extension " + extension +
                                            " is not supported, and a file that requires it cannot be rendered "
                                            "(facet implements " +
                                            implementedList() + ")");
  std::vector<std::pair<std::string, std::string>> seen;
  for (const std::string& extension : model.extensionsUsed) seen.push_back({extension, "extensionsUsed"});
  collectExtensions(model, seen);
  std::set<std::string> warned;
  for (const auto& [extension, where] : seen)
    if (!implemented(extension) && warned.insert(extension).second)
      reader.warn(where.front() == '.' ? where.substr(1) : where, ignoredExtension(extension));
}

void warnOfIgnoredFeatures(const tinygltf::Model& model, const GltfReader& reader) {
  for (std::size_t i = 0; i < model.meshes.size(); ++i)
    for (std::size_t p = 0; p < model.meshes[i].primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = model.meshes[i].primitives[p];
      const std::string at = "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(p) + "]";
      for (const auto& [name, accessor] : primitive.attributes) {
        const std::string where = at + ".attributes." + name;
        if (name.rfind("COLOR_", 0) == 0 && name != "COLOR_0")
          reader.warn(where, "only COLOR_0 is read; this set of vertex colours is not");
        else if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0)
          reader.warn(where, "skinning is not read; meshes render in their bind pose");
      }
      for (std::size_t t = 0; t < primitive.targets.size(); ++t)
        for (const auto& [name, accessor] : primitive.targets[t])
          if (name != "POSITION" && name != "NORMAL" && name != "TANGENT")
            reader.warn(at + ".targets[" + std::to_string(t) + "]." + name,
                        "a morph target's " + name + " is not read; its POSITION, NORMAL and TANGENT are");
    }
  if (!model.animations.empty()) reader.warn("animations", "animations are not read; the scene renders unanimated");
}

void GltfReader::warn(const std::string& where, const std::string& what) const {
  const auto same = std::find_if(warnings_.begin(), warnings_.end(), [&](const Warning& w) { return w.what == what; });
  if (same != warnings_.end())
    ++same->repeats;
  else
    warnings_.push_back({where, what});
}

std::vector<std::string> GltfReader::warnings() const {
  std::vector<std::string> lines;
  for (const Warning& w : warnings_)
    lines.push_back(source_ + ": " + w.where +
                    (w.repeats > 0 ? " (and " + std::to_string(w.repeats) + " more)" : std::string()) + ": " + w.what);
  return lines;
}

}  // namespace facet::scene::detail

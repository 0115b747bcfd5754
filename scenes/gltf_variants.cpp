// KHR_materials_variants: a file's named sets of materials, one chosen by
// name at load; without a name each primitive keeps its own material, as
// the extension's default.
#include <algorithm>

#include "scenes/gltf_internal.h"

namespace facet::scene::detail {
namespace {

constexpr const char* kExtension = "KHR_materials_variants";

// The file's variant names, in order; none where it declares no variants.
std::vector<std::string> variantNames(const tinygltf::Model& model, const GltfReader& reader) {
  const auto found = model.extensions.find(kExtension);
  if (found == model.extensions.end()) return {};
  const std::string where = std::string("extensions.") + kExtension + ".variants";
  const tinygltf::Value& variants = found->second.Get("variants");
  if (!variants.IsArray()) reader.fail(where, "must be an array of variants");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < variants.ArrayLen(); ++i) {
    const tinygltf::Value& name = variants.Get(int(i)).Get("name");
    if (!name.IsString()) reader.fail(where + "[" + std::to_string(i) + "].name", "must be a string");
    names.push_back(name.Get<std::string>());
  }
  return names;
}

}  // namespace

GltfVariant chosenVariant(const tinygltf::Model& model, const std::string& name, const GltfReader& reader) {
  const std::vector<std::string> names = variantNames(model, reader);
  const GltfVariant none{-1, int(names.size()), int(model.materials.size())};
  if (name.empty()) return none;
  const auto found = std::find(names.begin(), names.end(), name);
  if (found != names.end()) return {int(found - names.begin()), none.count, none.materials};
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
  reader.fail(std::string("extensions.") + kExtension,
              "no material variant is named '" + name + "' " +
                  (names.empty() ? std::string("(the file declares none)") : "(the file's: " + list + ")"));
}

int variantMaterial(const tinygltf::Primitive& primitive, GltfVariant variant, const GltfReader& reader,
                    const std::string& where) {
  const auto found = primitive.extensions.find(kExtension);
  if (found == primitive.extensions.end()) return primitive.material;
  const std::string at = where + ".extensions." + kExtension + ".mappings";
  const tinygltf::Value& mappings = found->second.Get("mappings");
  if (!mappings.IsArray()) reader.fail(at, "must be an array of mappings");
  int chosen = primitive.material;
  for (std::size_t m = 0; m < mappings.ArrayLen(); ++m) {
    const std::string mapping = at + "[" + std::to_string(m) + "]";
    const tinygltf::Value& material = mappings.Get(int(m)).Get("material");
    const tinygltf::Value& variants = mappings.Get(int(m)).Get("variants");
    if (!material.IsInt() || material.Get<int>() < 0 || material.Get<int>() >= variant.materials)
      reader.fail(mapping + ".material",
                  "must be the index of one of the file's " + std::to_string(variant.materials) + " materials");
    if (!variants.IsArray()) reader.fail(mapping + ".variants", "must be an array of variant indices");
    for (std::size_t v = 0; v < variants.ArrayLen(); ++v) {
      const tinygltf::Value& index = variants.Get(int(v));
      if (!index.IsInt() || index.Get<int>() < 0 || index.Get<int>() >= variant.count)
        reader.fail(mapping + ".variants[" + std::to_string(v) + "]",
                    "must be the index of one of the file's " + std::to_string(variant.count) + " variants");
      if (index.Get<int>() == variant.index) chosen = material.Get<int>();
    }
  }
  return chosen;
}

}  // namespace facet::scene::detail

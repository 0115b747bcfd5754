// The JSON types of the glTF 2.0 core properties, from the specification's
// JSON schema (glTF 2.0, chapter 5), checked on the file as written.
// tinygltf reads a property of the wrong type as if it were absent: a
// string for `extensionsRequired`, an object for a node's `children`, "0"
// for a primitive's `material` would render another file than the one
// written, with no word. Extensions' own members are checked where they are
// read (gltf_transmission.cpp, `member`).
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "scenes/gltf_internal.h"

namespace facet::scene::detail {
namespace {

enum class JsonType { Any, Object, Array, Number, Integer, String, Boolean };

// A property of an object: its type; for an array, its elements' type; for
// an object or an array of objects, the properties of each.
struct Property {
  std::string_view name;
  JsonType type;
  JsonType elements = JsonType::Any;
  const std::vector<Property>* members = nullptr;
};

using Properties = std::vector<Property>;
constexpr JsonType kObject = JsonType::Object, kArray = JsonType::Array, kNumber = JsonType::Number,
                   kInteger = JsonType::Integer, kString = JsonType::String, kBoolean = JsonType::Boolean;

const Properties kTextureInfo = {{"index", kInteger}, {"texCoord", kInteger}, {"scale", kNumber},
                                 {"strength", kNumber}, {"extensions", kObject}};
const Properties kMetallicRoughness = {{"baseColorFactor", kArray, kNumber},
                                       {"baseColorTexture", kObject, JsonType::Any, &kTextureInfo},
                                       {"metallicFactor", kNumber},
                                       {"roughnessFactor", kNumber},
                                       {"metallicRoughnessTexture", kObject, JsonType::Any, &kTextureInfo}};
const Properties kMaterial = {{"name", kString},
                              {"pbrMetallicRoughness", kObject, JsonType::Any, &kMetallicRoughness},
                              {"normalTexture", kObject, JsonType::Any, &kTextureInfo},
                              {"occlusionTexture", kObject, JsonType::Any, &kTextureInfo},
                              {"emissiveTexture", kObject, JsonType::Any, &kTextureInfo},
                              {"emissiveFactor", kArray, kNumber},
                              {"alphaMode", kString},
                              {"alphaCutoff", kNumber},
                              {"doubleSided", kBoolean},
                              {"extensions", kObject}};
const Properties kPrimitive = {{"attributes", kObject, kInteger}, {"indices", kInteger}, {"material", kInteger},
                               {"mode", kInteger}, {"targets", kArray, kObject}, {"extensions", kObject}};
const Properties kMesh = {{"name", kString}, {"primitives", kArray, kObject, &kPrimitive}, {"weights", kArray, kNumber}};
const Properties kNode = {{"name", kString},         {"children", kArray, kInteger}, {"mesh", kInteger},
                          {"camera", kInteger},      {"skin", kInteger},             {"matrix", kArray, kNumber},
                          {"translation", kArray, kNumber}, {"rotation", kArray, kNumber}, {"scale", kArray, kNumber},
                          {"weights", kArray, kNumber}, {"extensions", kObject}};
const Properties kScene = {{"name", kString}, {"nodes", kArray, kInteger}};
const Properties kPerspective = {{"aspectRatio", kNumber}, {"yfov", kNumber}, {"zfar", kNumber}, {"znear", kNumber}};
const Properties kOrthographic = {{"xmag", kNumber}, {"ymag", kNumber}, {"zfar", kNumber}, {"znear", kNumber}};
const Properties kCamera = {{"name", kString},
                            {"type", kString},
                            {"perspective", kObject, JsonType::Any, &kPerspective},
                            {"orthographic", kObject, JsonType::Any, &kOrthographic}};
const Properties kTexture = {{"name", kString}, {"sampler", kInteger}, {"source", kInteger}, {"extensions", kObject}};
const Properties kImage = {{"name", kString}, {"uri", kString}, {"mimeType", kString}, {"bufferView", kInteger}};
const Properties kSampler = {
    {"name", kString}, {"magFilter", kInteger}, {"minFilter", kInteger}, {"wrapS", kInteger}, {"wrapT", kInteger}};
const Properties kAccessor = {{"name", kString},        {"bufferView", kInteger}, {"byteOffset", kInteger},
                              {"componentType", kInteger}, {"normalized", kBoolean}, {"count", kInteger},
                              {"type", kString},        {"max", kArray, kNumber},  {"min", kArray, kNumber},
                              {"sparse", kObject}};
const Properties kBufferView = {{"name", kString},       {"buffer", kInteger}, {"byteOffset", kInteger},
                                {"byteLength", kInteger}, {"byteStride", kInteger}, {"target", kInteger}};
const Properties kBuffer = {{"name", kString}, {"uri", kString}, {"byteLength", kInteger}};
const Properties kAsset = {
    {"version", kString}, {"minVersion", kString}, {"generator", kString}, {"copyright", kString}};
const Properties kRoot = {{"asset", kObject, JsonType::Any, &kAsset},
                          {"scene", kInteger},
                          {"scenes", kArray, kObject, &kScene},
                          {"nodes", kArray, kObject, &kNode},
                          {"meshes", kArray, kObject, &kMesh},
                          {"materials", kArray, kObject, &kMaterial},
                          {"textures", kArray, kObject, &kTexture},
                          {"images", kArray, kObject, &kImage},
                          {"samplers", kArray, kObject, &kSampler},
                          {"accessors", kArray, kObject, &kAccessor},
                          {"bufferViews", kArray, kObject, &kBufferView},
                          {"buffers", kArray, kObject, &kBuffer},
                          {"cameras", kArray, kObject, &kCamera},
                          {"skins", kArray, kObject},
                          {"animations", kArray, kObject},
                          {"extensionsUsed", kArray, kString},
                          {"extensionsRequired", kArray, kString},
                          {"extensions", kObject}};

bool hasType(const nlohmann::json& value, JsonType type) {
  switch (type) {
    case JsonType::Any: return true;
    case JsonType::Object: return value.is_object();
    case JsonType::Array: return value.is_array();
    case JsonType::Number: return value.is_number();
    case JsonType::Integer: return value.is_number_integer();
    case JsonType::String: return value.is_string();
    case JsonType::Boolean: return value.is_boolean();
  }
  return false;
}

std::string_view typeName(JsonType type) {
  switch (type) {
    case JsonType::Any: break;
    case JsonType::Object: return "an object";
    case JsonType::Array: return "an array";
    case JsonType::Number: return "a number";
    case JsonType::Integer: return "a whole number";
    case JsonType::String: return "a string";
    case JsonType::Boolean: return "true or false";
  }
  return "any value";
}

void checkType(const nlohmann::json& value, JsonType type, const std::string& at, const std::string& source) {
  if (hasType(value, type)) return;
  constexpr std::size_t kShownCharacters = 40;
  std::string shown = value.dump();
  if (shown.size() > kShownCharacters) shown = shown.substr(0, kShownCharacters) + "...";
  throw InputError(source, 0, at, "must be " + std::string(typeName(type)) + " (glTF 2.0), is " + shown);
}

void checkMembers(const nlohmann::json& object, const Properties& properties, const std::string& at,
                  const std::string& source) {
  for (const Property& property : properties) {
    const auto found = object.find(property.name);
    if (found == object.end()) continue;
    const std::string where = (at.empty() ? "" : at + ".") + std::string(property.name);
    checkType(*found, property.type, where, source);
    if (property.type == kObject && property.members) checkMembers(*found, *property.members, where, source);
    // An object property with an element type holds values of that type.
    const bool eachMember = property.type == kArray || property.elements != JsonType::Any;
    if (!eachMember) continue;
    std::size_t i = 0;
    for (const auto& [key, element] : found->items()) {
      const std::string item = where + (found->is_array() ? "[" + std::to_string(i++) + "]" : "." + key);
      checkType(element, property.elements, item, source);
      if (property.members && element.is_object()) checkMembers(element, *property.members, item, source);
    }
  }
}

}  // namespace

void checkPropertyTypes(const nlohmann::json& gltf, const std::string& source) { checkMembers(gltf, kRoot, "", source); }

}  // namespace facet::scene::detail

// glTF 2.0 scenes through tinygltf; the mapping to facet's scene is
// docs/gltf.md.
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <optional>
#include <utility>
#include <string_view>
#include <system_error>

#include "scenes/gltf_internal.h"
#include "scenes/image_decoder.h"
#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/memory_budget.h"
#include "scenes/scene_file.h"

namespace facet::scene {
namespace {

// tinygltf's JSON parser recurses once per nested array or object, so deep
// enough nesting overflows the stack; glTF itself nests fewer than 20 levels.
constexpr int kMaxJsonNesting = 512;

// The deepest nesting of arrays and objects in `json`, outside strings,
// counted up to one past `limit`.
int jsonNesting(std::string_view json, int limit) {
  int depth = 0, deepest = 0;
  bool inString = false, escaped = false;
  for (char c : json) {
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) break;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

// The JSON chunk of a .glb file (glTF 2.0, 4.4): 12 bytes of header, then the
// chunk's length and type. A file too short for them is left to tinygltf.
std::string_view glbJson(std::string_view file) {
  if (file.size() < 20) return file;
  std::uint32_t length;
  std::memcpy(&length, file.data() + 12, 4);
  return file.substr(20, length);
}

// An image stored in a buffer view is decoded by tinygltf while it parses,
// from a pointer it does not bound: every such view must lie inside its
// buffer before tinygltf sees the file.
void checkImageViews(const nlohmann::json& gltf, const std::string& source) {
  if (!gltf.contains("images") || !gltf["images"].is_array()) return;
  const auto list = [&](const char* name) {
    return gltf.contains(name) && gltf[name].is_array() ? gltf[name] : nlohmann::json::array();
  };
  const nlohmann::json views = list("bufferViews"), buffers = list("buffers");
  const auto number = [](const nlohmann::json& object, const char* key) -> double {
    return object.is_object() && object.contains(key) && object[key].is_number() ? object[key].get<double>() : 0.0;
  };
  for (std::size_t i = 0; i < gltf["images"].size(); ++i) {
    const nlohmann::json& image = gltf["images"][i];
    if (!image.is_object() || !image.contains("bufferView")) continue;
    const std::string where = "images[" + std::to_string(i) + "].bufferView";
    const double view = number(image, "bufferView");
    if (!(view >= 0 && view < double(views.size())))
      throw InputError(source, 0, where,
                       "index out of range (the file has " + std::to_string(views.size()) + " buffer views)");
    const nlohmann::json& v = views[std::size_t(view)];
    const double buffer = number(v, "buffer");
    if (!(buffer >= 0 && buffer < double(buffers.size())))
      throw InputError(source, 0, where, "its view's buffer index is out of range");
    const double end = number(v, "byteOffset") + number(v, "byteLength");
    if (!(end <= number(buffers[std::size_t(buffer)], "byteLength")))
      throw InputError(source, 0, where, "its view ends past the end of its buffer");
  }
}

// A number of a texture coordinate scale within kMaxTextureScale
// (scenes/texture.h); what is not a number is left to the material's reader.
void checkTextureScale(const nlohmann::json& value, const std::string& where, const std::string& source) {
  if (value.is_number() && !(std::abs(value.get<double>()) <= kMaxTextureScale))
    throw InputError(source, 0, where,
                     "must be within -1e6 to 1e6 (the GPU computes texture coordinates in float), is " + value.dump());
}

// tinygltf reads a texture info's `index` and `texCoord` into an int, wrapping
// values past its range and reading a fraction as if it were absent (glTF
// 2.0, 5.22: both are integers, at least 0), so they are checked as written. `extras`
// are the author's own and hold no texture infos.
void checkTextureInfos(const nlohmann::json& value, const std::string& where, const std::string& source) {
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i)
      checkTextureInfos(value[i], where + "[" + std::to_string(i) + "]", source);
  if (!value.is_object()) return;
  for (const auto& [key, member] : value.items()) {
    const std::string at = where + "." + key;
    const bool whole = member.is_number_unsigned() ? member.get<std::uint64_t>() <= std::uint64_t(INT_MAX)
                                                   : member.is_number_integer() && member.get<std::int64_t>() >= 0 &&
                                                         member.get<std::int64_t>() <= INT_MAX;
    if ((key == "index" || key == "texCoord") && !whole)
      throw InputError(source, 0, at,
                       std::string("must be a whole number from 0 to 2147483647 (") +
                           (key == "index" ? "a texture's index" : "the n of the TEXCOORD_n it reads") + "), is " +
                           member.dump());
    if (key == "KHR_texture_transform" && member.contains("scale") && member["scale"].is_array())
      for (std::size_t i = 0; i < member["scale"].size(); ++i)
        checkTextureScale(member["scale"][i], at + ".scale[" + std::to_string(i) + "]", source);
    if ((key == "normalTexture" || key == "clearcoatNormalTexture") && member.contains("scale"))
      checkTextureScale(member["scale"], at + ".scale", source);
    if (key != "extras") checkTextureInfos(member, at, source);
  }
}

// The parts of the file that tinygltf would read unsafely or misread, checked
// on the JSON as written. Malformed JSON is left to tinygltf.
void checkBeforeParsing(std::string_view json, const std::string& source) {
  const nlohmann::json gltf = nlohmann::json::parse(json, nullptr, false);
  if (!gltf.is_object()) return;
  checkImageViews(gltf, source);
  if (gltf.contains("materials")) checkTextureInfos(gltf["materials"], "materials", source);
  detail::checkPropertyTypes(gltf, source);
}

// What tinygltf reads besides the file itself goes through facet's own checks:
// every file it names (images and buffers) must be a regular file, and every
// image is decoded by facet's decoder, its header checked against the size
// and memory limits before a texel is decoded. tinygltf's callbacks cannot
// throw through it, so the first refusal is kept and thrown once it returns.
struct ExternalReads {
  std::string source;
  std::exception_ptr refusal;
  std::uint64_t heldBytes = 0;  // what the images decoded so far keep, and their textures

  bool refuse(std::string* error) {
    if (!refusal) refusal = std::current_exception();
    if (error) error->append("refused by facet\n");
    return false;
  }
};

// A path names an existing file by stat alone: tinygltf's own test opens it,
// and opening a FIFO blocks until a writer comes.
bool fileExists(const std::string& path, void*) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

std::string sameFilePath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user) {
  auto& reads = *static_cast<ExternalReads*>(user);
  try {
    checkInputFile(path, "a file that " + reads.source + " names");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot open a file that " + reads.source + " names", "the file cannot be read");
    out->assign(std::istreambuf_iterator<char>(in), {});
    return true;
  } catch (...) {
    return reads.refuse(error);
  }
}

bool decodeGltfImage(tinygltf::Image* image, const int index, std::string* error, std::string*, int, int,
                     const unsigned char* bytes, int size, void* user) {
  auto& reads = *static_cast<ExternalReads*>(user);
  try {
    const std::string field =
        "images[" + std::to_string(index) + "]" + (image->uri.empty() ? "" : " '" + image->uri + "'");
    const DecodedSamples decoded =
        decodeSamples({bytes, std::size_t(std::max(size, 0))}, reads.source, field, kMaxTextureSize, reads.heldBytes);
    image->width = decoded.width;
    image->height = decoded.height;
    image->component = decoded.components;
    image->bits = 8 * decoded.bytesPerSample;
    image->pixel_type =
        decoded.bytesPerSample == 2 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(decoded.samples.get(), decoded.samples.get() + decoded.byteCount());
    reads.heldBytes += textureHeldBytes(decoded.width, decoded.height, decoded.components, decoded.bytesPerSample);
    return true;
  } catch (...) {
    return reads.refuse(error);
  }
}

// The primitives of `mesh` by the scene material they use in `variant`, in
// the order each material first appears: every group becomes one object, so
// each primitive keeps its own material while those sharing one weld into
// one cage.
std::vector<std::pair<int, std::vector<std::size_t>>> materialGroups(const tinygltf::Mesh& mesh,
                                                                     int defaultMaterialIndex,
                                                                     detail::GltfVariant variant,
                                                                     const detail::GltfReader& reader,
                                                                     const std::string& where) {
  std::vector<std::pair<int, std::vector<std::size_t>>> groups;
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const std::string primitive = where + ".primitives[" + std::to_string(p) + "]";
    const int material = detail::variantMaterial(mesh.primitives[p], variant, reader, primitive);
    if (material < -1 || material >= defaultMaterialIndex)
      reader.fail(primitive + ".material", "material index " + std::to_string(material) +
                                               " out of range (the file has " + std::to_string(defaultMaterialIndex) +
                                               " materials)");
    const int index = material >= 0 ? material : defaultMaterialIndex;
    auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == index; });
    if (group == groups.end()) group = groups.insert(groups.end(), {index, {}});
    group->second.push_back(p);
  }
  return groups;
}

// Per material of the file, then the default material: whether a primitive
// with vertex colours (COLOR_0) uses it in `variant`.
std::vector<bool> materialsWithVertexColours(const tinygltf::Model& model, detail::GltfVariant variant,
                                             const detail::GltfReader& reader) {
  std::vector<bool> coloured(model.materials.size() + 1, false);
  for (std::size_t i = 0; i < model.meshes.size(); ++i)
    for (std::size_t p = 0; p < model.meshes[i].primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = model.meshes[i].primitives[p];
      const int material = detail::variantMaterial(
          primitive, variant, reader, "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(p) + "]");
      if (primitive.attributes.count("COLOR_0") && material < int(model.materials.size()))
        coloured[material >= 0 ? std::size_t(material) : model.materials.size()] = true;
    }
  return coloured;
}

// The name of a mesh instance's object `k`: the mesh's name, then name.1, name.2, ...
std::string objectName(const std::string& mesh, std::size_t k) {
  std::string name = mesh;
  if (k > 0) name.append(".").append(std::to_string(k));
  return name;
}

// The file read and parsed by tinygltf, its external files and images read
// through the checks here; `warning` gets tinygltf's warnings.
tinygltf::Model parseGltf(const std::filesystem::path& path, std::string& warning) {
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, 0, "cannot load glTF", "cannot open the file");
  const std::string file{std::istreambuf_iterator<char>(in), {}};
  const bool binary = path.extension() == ".glb";
  if (jsonNesting(binary ? glbJson(file) : file, kMaxJsonNesting) > kMaxJsonNesting)
    throw InputError(source, 0, "JSON nesting",
                     "arrays and objects nest deeper than " + std::to_string(kMaxJsonNesting) + " levels");
  checkBeforeParsing(binary ? glbJson(file) : file, source);
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  ExternalReads reads{source, nullptr};
  loader.SetFsCallbacks({&fileExists, &sameFilePath, &readWholeFile, nullptr, &reads});
  loader.SetImageLoader(&decodeGltfImage, &reads);
  std::string error;
  const std::string baseDir = path.parent_path().string();
  const bool ok =
      binary
          ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(file.data()),
                                        unsigned(file.size()), baseDir)
          : loader.LoadASCIIFromString(&model, &error, &warning, file.data(), unsigned(file.size()), baseDir);
  if (reads.refusal) std::rethrow_exception(reads.refusal);
  if (!ok) throw InputError(source, 0, "cannot load glTF", error.empty() ? "unknown tinygltf error" : error);
  return model;
}

// The first of `textures`' slots that reads TEXCOORD_1, by the name its
// material in the file gives it; none where no slot does.
std::optional<std::string> slotOnSecondTexcoords(const materials::MaterialTextures& t) {
  const std::pair<const char*, const materials::TextureSlot*> slots[] = {
      {"pbrMetallicRoughness.baseColorTexture", &t.baseColorTexture},
      {"pbrMetallicRoughness.metallicRoughnessTexture", &t.metallicRoughnessTexture},
      {"normalTexture", &t.normalTexture},
      {"occlusionTexture", &t.occlusionTexture},
      {"emissiveTexture", &t.emissiveTexture},
      {"extensions.KHR_materials_clearcoat.clearcoatTexture", &t.clearcoatTexture},
      {"extensions.KHR_materials_clearcoat.clearcoatRoughnessTexture", &t.clearcoatRoughnessTexture},
      {"extensions.KHR_materials_clearcoat.clearcoatNormalTexture", &t.clearcoatNormalTexture},
      {"extensions.KHR_materials_sheen.sheenColorTexture", &t.sheenColorTexture},
      {"extensions.KHR_materials_sheen.sheenRoughnessTexture", &t.sheenRoughnessTexture},
      {"extensions.KHR_materials_anisotropy.anisotropyTexture", &t.anisotropyTexture},
      {"extensions.KHR_materials_transmission.transmissionTexture", &t.transmissionTexture},
      {"extensions.KHR_materials_specular.specularTexture", &t.specularTexture},
      {"extensions.KHR_materials_specular.specularColorTexture", &t.specularColorTexture},
      {"extensions.KHR_materials_iridescence.iridescenceTexture", &t.iridescenceTexture},
      {"extensions.KHR_materials_iridescence.iridescenceThicknessTexture", &t.iridescenceThicknessTexture}};
  for (const auto& slot : slots)
    if (slot.second->texture >= 0 && slot.second->texCoord == 1) return slot.first;
  return std::nullopt;
}

// The objects of the mesh instance at `node` (nodes[index] as `where`), one
// per material of its primitives, at `world`.
void addMeshObjects(Scene& scene, const tinygltf::Model& model, const tinygltf::Node& node, const std::string& where,
                    const glm::dmat4& world, int defaultMaterialIndex, const std::vector<detail::GltfCutout>& cutouts,
                    detail::GltfVariant variant, const detail::GltfReader& reader) {
  if (std::size_t(node.mesh) >= model.meshes.size()) reader.fail(where, "mesh index out of range");
  const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
  const std::string meshWhere = "meshes[" + std::to_string(node.mesh) + "]";
  const std::size_t firstObject = scene.objects.size();
  const std::vector<double> weights = detail::morphWeights(node, mesh, reader, where, meshWhere);
  for (const auto& [material, primitives] : materialGroups(mesh, defaultMaterialIndex, variant, reader, meshWhere)) {
    Object object;
    object.name = objectName(mesh.name.empty() ? where : mesh.name, scene.objects.size() - firstObject);
    object.cage = detail::toCage(mesh, primitives, world, weights,
                                 detail::tangentTexcoordSet(model, material, scene.materials[std::size_t(material)]),
                                 reader, meshWhere);
    if (object.cage.faceCount() == 0) continue;  // only triangles without area
    object.subdivision = Subdivision::None;
    object.material = material;
    // glTF culls the back faces of a material that is not doubleSided,
    // its default material's included.
    object.oneSided = material == defaultMaterialIndex || !model.materials[std::size_t(material)].doubleSided;
    const std::optional<materials::MaterialTextures>& textures = scene.materials[std::size_t(material)].textures;
    if (textures && object.cage.texcoords1.empty())
      if (const std::optional<std::string> slot = slotOnSecondTexcoords(*textures))
        reader.fail(meshWhere, "materials[" + std::to_string(material) + "]." + *slot +
                                   ".texCoord is 1, but not every primitive of this mesh in that material has "
                                   "TEXCOORD_1, which it reads");
    if (material != defaultMaterialIndex) {
      object.alphaMode = cutouts[std::size_t(material)].mode;
      object.alphaCutoff = cutouts[std::size_t(material)].cutoff;
      object.alphaFactor = cutouts[std::size_t(material)].factor;
      if (const auto& t = scene.materials[std::size_t(material)].textures) object.alphaTexture = t->baseColorTexture;
    }
    scene.objects.push_back(std::move(object));
  }
  if (scene.objects.size() == firstObject) reader.fail(meshWhere, "has no faces");
}

}  // namespace

Scene loadGltfScene(const std::filesystem::path& path, const std::string& variant) {
  const std::string source = path.string();
  std::string warning;
  tinygltf::Model model = parseGltf(path, warning);
  const detail::GltfReader reader(model, source);
  detail::checkExtensions(model, reader);
  for (std::size_t start = 0; start < warning.size();) {  // tinygltf's, one per line
    const std::size_t end = std::min(warning.find('\n', start), warning.size());
    if (end > start) reader.warn("tinygltf", warning.substr(start, end - start));
    start = end + 1;
  }
  const detail::GltfVariant chosen = detail::chosenVariant(model, variant, reader);
  detail::warnOfIgnoredFeatures(model, reader);

  Scene scene;
  scene.source = path;
  detail::TextureTable textures(model, reader, scene.textures);
  const std::vector<bool> coloured = materialsWithVertexColours(model, chosen, reader);
  std::vector<detail::GltfCutout> cutouts;
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    scene.materials.push_back(detail::toMaterial(model.materials[i], i, reader, textures, coloured[i]));
    cutouts.push_back(detail::readCutout(model.materials[i], i, reader));
  }
  const int defaultMaterialIndex = int(scene.materials.size());
  scene.materials.push_back(defaultMaterial());
  if (coloured.back()) {
    // defaultMaterial()'s diffuse 0.5, F(0) 0.04 and alpha 0.25 as glTF parameters.
    materials::MaterialTextures t;
    t.baseColor = glm::dvec3(0.5);
    t.metallic = 0.0;
    t.roughness = 0.5;
    scene.materials.back().textures = t;
  }

  std::optional<Camera> camera;
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (int root : detail::sceneRoots(model, reader)) stack.push_back({root, glm::dmat4(1.0)});
  while (!stack.empty()) {
    auto [index, parent] = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[std::size_t(index)];
    const std::string where = "nodes[" + std::to_string(index) + "]";
    const glm::dmat4 world = parent * detail::localTransform(node);
    if (node.mesh >= 0) addMeshObjects(scene, model, node, where, world, defaultMaterialIndex, cutouts, chosen, reader);
    if (node.camera >= 0 && !camera) {
      if (std::size_t(node.camera) >= model.cameras.size()) reader.fail(where, "camera index out of range");
      const tinygltf::Camera& c = model.cameras[std::size_t(node.camera)];
      if (c.type == "perspective")
        camera = detail::toCamera(c, node.camera, world, reader, where);
      else
        reader.warn(where + ".camera",
                    "only perspective cameras are read; the view is the first perspective "
                    "camera's, or one framing the scene");
    }
    if (auto light = node.extensions.find("KHR_lights_punctual");
        light != node.extensions.end() && light->second.Has("light")) {
      const int lightIndex = light->second.Get("light").GetNumberAsInt();
      if (lightIndex < 0 || std::size_t(lightIndex) >= model.lights.size())
        reader.fail(where, "KHR_lights_punctual light index out of range");
      scene.lights.push_back(detail::toLight(model.lights[std::size_t(lightIndex)], lightIndex, world, reader, where));
    }
    for (int child : node.children) stack.push_back({child, world});
  }
  if (scene.objects.empty()) throw InputError(source, 0, "no meshes", "the glTF scene has no node with a mesh");
  scene.camera = camera ? *camera : frameBounds(cageBounds(scene));
  if (scene.lights.empty()) addDefaultLighting(scene);
  scene.warnings = reader.warnings();
  return scene;
}

}  // namespace facet::scene

// Internal: the parts of the glTF 2.0 loader that its files share. Only
// scenes/gltf_*.cpp include this file.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <tiny_gltf.h>

#include <glm/mat4x4.hpp>

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "materials/parameter_table.h"
#include "scenes/scene.h"
#include "scenes/texture.h"
#include "scenes/input_error.h"

namespace facet::scene::detail {

// What an accessor's elements must be, from the glTF 2.0 specification's
// tables of mesh attributes and indices (3.7.2.1).
struct ElementFormat {
  std::size_t components;
  std::array<int, 3> componentTypes;  // unused slots repeat the first
  const char* name;
  bool normalizable = false;    // integer components may be normalized
  bool normalizedOnly = false;  // integer components must be
};
// The file's errors and its accessors (gltf_accessors.cpp).
class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, std::string source) : model_(model), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& rule) const {
    throw InputError(source_, 0, where, rule);
  }
  // Notes that facet renders field `where` otherwise than the file says, as
  // `what` tells; the same `what` again counts as one line naming the first
  // field (gltf_extensions.cpp).
  void warn(const std::string& where, const std::string& what) const;
  // One line per distinct warning: "FILE: FIELD: what", "FILE: FIELD (and N
  // more): what" when repeated.
  std::vector<std::string> warnings() const;

  // The elements of an accessor as doubles (components × count), checked
  // against `format` and against the bounds of its buffer, with its sparse
  // substitution applied; normalized integers of a format that allows them
  // map to [0, 1] (glTF 2.0, 3.11).
  std::vector<double> read(int accessorIndex, const std::string& where, const ElementFormat& format) const;
  // The accessor's components per element (VEC3 3, VEC4 4, ...).
  std::size_t components(int accessorIndex, const std::string& where) const;

 private:
  static double component(const unsigned char* p, int type);
  // The first of `count` elements of `elementBytes` at `byteOffset` in buffer
  // view `viewIndex`, and their stride, once they are checked to lie inside it.
  std::pair<const unsigned char*, std::size_t> elements(int viewIndex, std::size_t byteOffset, std::size_t count,
                                                        std::size_t elementBytes, const std::string& where,
                                                        const std::string& accessor) const;

  struct Warning {
    std::string where, what;
    int repeats = 0;
  };

  const tinygltf::Model& model_;
  std::string source_;
  mutable std::vector<Warning> warnings_;  // noted while the const reader reads the file
};

// The scene's textures, converted from the glTF file's as materials use
// them: one per glTF texture and encoding (gltf_materials.cpp).
class TextureTable {
 public:
  TextureTable(const tinygltf::Model& model, const GltfReader& reader, std::vector<Texture>& textures)
      : model_(model), reader_(reader), textures_(textures) {}

  // The slot of the texture info at field `where`: texture `index` with its
  // extensions. One on a coordinate set past TEXCOORD_1 is an error,
  // or, where `withoutIt` says how the surface renders without the slot (one
  // that only refines the look), no slot and a warning.
  materials::TextureSlot slot(const tinygltf::ExtensionMap& extensions, int index, int texCoord,
                              TextureEncoding encoding, const std::string& where, const char* withoutIt = nullptr);

 private:
  double number(const tinygltf::Value& value, const std::string& where) const;
  glm::dvec2 pair(const tinygltf::Value& transform, const char* key, const std::string& at, glm::dvec2 fallback) const;
  Texture convert(int index, TextureEncoding encoding) const;

  const tinygltf::Model& model_;
  const GltfReader& reader_;
  std::vector<Texture>& textures_;
  std::map<std::tuple<int, int, TextureEncoding>, int> cache_;  // (image, sampler, encoding) -> texture
};

// gltf_materials.cpp. A material some primitive with vertex colours uses
// (`vertexColours`) keeps its glTF parameters as for textures, so that the
// colour multiplies its base colour per hit.
materials::Material toMaterial(const tinygltf::Material& gltf, std::size_t index, const GltfReader& reader,
                               TextureTable& textures, bool vertexColours = false);

// gltf_materials.cpp: glTF's alphaMode of material `index` as an Object
// carries it (scenes/scene.h): the mode (MASK at a cutoff of 0 is opaque),
// MASK's alphaCutoff and the base colour factor's alpha.
struct GltfCutout {
  AlphaMode mode = AlphaMode::Opaque;
  double cutoff = 0.5;
  double factor = 1.0;
};
GltfCutout readCutout(const tinygltf::Material& gltf, std::size_t index, const GltfReader& reader);

// gltf_transmission.cpp: member `key` of extension object `value` at field
// `where`, a finite number; `fallback` when absent.
double member(const tinygltf::Value& value, const char* key, double fallback, const std::string& where,
              const GltfReader& reader);
// The rule a glTF factor breaks, if any: the bounds of the row of the
// material parameter it becomes (materials/parameter_table.h).
std::optional<std::string> factorRule(double value, materials::BoundedParameter parameter);
// Extension `name` of a material; null when it has none.
const tinygltf::Value* extension(const tinygltf::Material& gltf, const char* name);

// gltf_lobes.cpp: KHR_materials_clearcoat, _sheen, _iridescence and
// KHR_materials_anisotropy of `gltf` (field `material`) into `m`, whose
// transmission is already set.
void applyClearcoat(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                    materials::Material& m);
void applyIridescence(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                      materials::Material& m);
void applySheen(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                materials::Material& m);
void applyAnisotropy(const tinygltf::Material& gltf, const std::string& material, const GltfReader& reader,
                     materials::Material& m);
// The same extensions' textures, and KHR_materials_transmission's and
// _specular's, into `t` (`m` with its factors applied): whether it reads
// any.
bool readLayerTextures(const tinygltf::Material& gltf, const materials::Material& m, const std::string& material,
                       const GltfReader& reader, TextureTable& textures, materials::MaterialTextures& t);

// The dielectric's F(0) factors of KHR_materials_ior and
// KHR_materials_specular: F(0) of the index × specularColorFactor, and
// specularFactor (rules/shading/textured_material.h, dielectric_specular_f0).
struct DielectricSpecular {
  glm::dvec3 color;
  double factor;
};

// gltf_transmission.cpp: KHR_materials_ior, KHR_materials_specular,
// KHR_materials_transmission and KHR_materials_volume of `gltf` (field
// `material`) into `m`, whose base colour factor and metallic factor are
// `base` and `metallic`; returns the dielectric's F(0) factors, which a
// textured material applies per hit.
DielectricSpecular applyTransmission(const tinygltf::Material& gltf, const std::string& material,
                                     const GltfReader& reader, const glm::dvec3& base, double metallic,
                                     materials::Material& m);

// gltf_meshes.cpp: adds `primitives` (indices into the mesh's, which share
// one material) of one mesh instance as one welded cage, with their NORMALs
// per face corner when every one has them (shading normals of the mesh as
// authored), and likewise their TEXCOORD_0 as a face-varying channel: one
// value per welded vertex and coordinate, so corners that share both stay
// joined and the rest form seams. Each primitive's morph targets move its
// POSITIONs and NORMALs by `weights` (one per target; morphWeights).
// Where `tangentSet` names the texture coordinates of a material that takes
// a tangent (tangentTexcoordSet) and the primitives have NORMALs, the cage
// carries tangents: each primitive's TANGENT, else MikkTSpace's
// (gltf_tangents.cpp).
ControlCage toCage(const tinygltf::Mesh& mesh, const std::vector<std::size_t>& primitives, const glm::dmat4& world,
                   const std::vector<double>& weights, std::optional<int> tangentSet, const GltfReader& reader,
                   const std::string& where);

// gltf_tangents.cpp. Whether material `index` would take a tangent: a
// normal map (its own or its clear coat's) or an anisotropic lobe.
bool usesTangents(const tinygltf::Model& model, int index);
// The set of texture coordinates material `index`'s
// tangents follow where it takes one (usesTangents): the set its normal map
// reads as `material` has it (KHR_texture_transform's texCoord included),
// else its coat's normal map's, else TEXCOORD_0; none where it takes none.
std::optional<int> tangentTexcoordSet(const tinygltf::Model& model, int index, const materials::Material& material);
// A primitive's TANGENTs (VEC4 FLOAT), moved by its morph targets' TANGENT
// by `weights` and turned into the world by `world`; each checked finite,
// nonzero and with a sign.
std::vector<glm::dvec4> primitiveTangents(const tinygltf::Primitive& primitive, std::size_t vertices,
                                          const glm::dmat4& world, const std::vector<double>& weights,
                                          const GltfReader& reader, const std::string& at);
// Fills the cage's corners whose tangent has w 0 (their primitive had no
// TANGENT) with MikkTSpace's, generated from its positions, normals and
// texture coordinates `set`; false, changing nothing, where the cage has no
// such coordinates.
bool completeTangents(ControlCage& cage, int set);

// `values` (3 per vertex) moved by each of the primitive's morph targets'
// `attribute` (VEC3 FLOAT) times its weight; a target without it moves
// nothing.
void morph(std::vector<double>& values, const tinygltf::Primitive& primitive, const char* attribute,
           const std::vector<double>& weights, const GltfReader& reader, const std::string& at);

// The weights of a mesh instance's morph targets (glTF 2.0, 3.7.2.2): the
// node's, else the mesh's, else 0 each; checked against every primitive's
// target count and for finite values.
std::vector<double> morphWeights(const tinygltf::Node& node, const tinygltf::Mesh& mesh, const GltfReader& reader,
                                 const std::string& nodeWhere, const std::string& meshWhere);

// gltf_schema.cpp: the JSON type of every core property, as written; throws
// InputError naming the property.
void checkPropertyTypes(const nlohmann::json& gltf, const std::string& source);

// gltf_variants.cpp: KHR_materials_variants. The variant named `name`
// among the file's `count` (index -1 for an empty name: each primitive's
// own material), and the file's material count; throws naming the file's
// variants where none has the name.
struct GltfVariant {
  int index = -1;
  int count = 0;
  int materials = 0;
};
GltfVariant chosenVariant(const tinygltf::Model& model, const std::string& name, const GltfReader& reader);
// The material index primitive `where` renders in `variant`: its mapping's
// where one lists the variant, else its own; every mapping is checked.
int variantMaterial(const tinygltf::Primitive& primitive, GltfVariant variant, const GltfReader& reader,
                    const std::string& where);

// gltf_extensions.cpp: refuses a file whose extensionsRequired names an
// extension facet does not implement (glTF 2.0, 3.12), and warns of each
// used one it ignores and of the core features it does not render as written.
void checkExtensions(const tinygltf::Model& model, const GltfReader& reader);
void warnOfIgnoredFeatures(const tinygltf::Model& model, const GltfReader& reader);

// gltf_nodes.cpp
glm::dmat4 localTransform(const tinygltf::Node& node);
// Light `index` of KHR_lights_punctual, placed by node `where`.
Light toLight(const tinygltf::Light& gltf, int index, const glm::dmat4& world, const GltfReader& reader,
              const std::string& where);
// Perspective camera `index`, placed by node `where` and its world matrix.
Camera toCamera(const tinygltf::Camera& gltf, int index, const glm::dmat4& world, const GltfReader& reader,
                const std::string& where);
// The roots of the scene to render, once the node hierarchy is checked to be
// the forest glTF requires (2.0, 3.5.3): a node has at most one parent, and a
// root has none and is listed once.
std::vector<int> sceneRoots(const tinygltf::Model& model, const GltfReader& reader);

}  // namespace facet::scene::detail

// Scene files in, validated plain data out.
//
//   .json         facet's scene format (docs/scene-format.md)
//   .obj          a bare OpenSubdiv-style control cage, subdivided
//   .gltf / .glb  glTF 2.0: meshes rendered as authored, metallic-roughness
//                 materials, cameras and KHR_lights_punctual lights
//
// A scene without a camera is framed from the default direction; one without
// lights gets the default lighting (addDefaultLighting). Errors throw
// InputError naming the file, the line or field, and the rule.
//
// `overrides` (--set, json_overrides.h) change a .json scene's document
// before it is read; a .obj or glTF model takes them for its render, camera
// and environment only (docs/scene-format.md, "The command line: --material and --set").
#pragma once

#include <glm/mat4x4.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenes/json_overrides.h"
#include "scenes/scene.h"

namespace facet::scene {

// `variant`: a glTF file's material variant by name (KHR_materials_variants);
// empty for each primitive's own material.
Scene loadScene(const std::filesystem::path& path, std::span<const JsonOverride> overrides = {},
                const std::string& variant = {});

Scene loadJsonScene(const std::filesystem::path& path, std::span<const JsonOverride> overrides = {});
// A scene file's JSON, parsed; errors name the file.
nlohmann::json readSceneDocument(const std::filesystem::path& path);
// A document read as a scene file is, its files relative to `folder`, its
// errors naming `source` in place of a file (the APIs' dict form).
Scene sceneFromJson(const nlohmann::json& document, const std::filesystem::path& folder, const std::string& source);
Scene loadGltfScene(const std::filesystem::path& path, const std::string& variant = {});
Scene sceneFromCage(ControlCage cage);

// The render, camera and environment fields of `overrides` over a model
// that is not a JSON scene, read as a scene file's; paths relative to
// `modelFile`. Any other field throws std::invalid_argument naming --set.
void applyModelOverrides(Scene& scene, const std::filesystem::path& modelFile, std::span<const JsonOverride> overrides);

// A material as `facet render --material` names it: a material file (a name
// ending in .json, relative to the working folder) or a preset at the
// default material's roughness. The textures a file reads are appended to
// `textures`. Errors name the file and field, or --material.
materials::Material loadMaterialReference(const std::string& reference, std::vector<Texture>& textures);

// `material` on every object called `objectName`, or on every object when
// it is empty; throws std::invalid_argument listing the objects' names
// when no object has that name.
void assignMaterial(Scene& scene, const std::string& objectName, materials::Material material);

// Blocks of a scene file read from JSON values by the file's rules, each
// error naming the field as the file does and `source` in place of the file:
// the API's scene edits go through them, so that an edit obeys exactly what
// a file does. Files they name are relative to the folder of `relativeTo`,
// as a scene file's are to the file's.
Camera readCameraBlock(const nlohmann::json& camera, const std::string& source);
std::vector<Light> readLightsBlock(const nlohmann::json& lights, const std::string& source);
// A block that names neither file nor color keeps `start`'s map.
Environment readEnvironmentBlock(const nlohmann::json& environment, const std::string& source,
                                 const std::filesystem::path& relativeTo, const std::optional<Environment>& start);
// objects[object].material: a preset name, a material file (.json) or the
// fields of a material; the textures it reads are appended to `textures`.
materials::Material readObjectMaterial(const nlohmann::json& material, int object, const std::string& source,
                                       const std::filesystem::path& relativeTo, std::vector<Texture>& textures);
// materials.NAME: a material of the scene's named materials.
materials::Material readNamedMaterial(const nlohmann::json& material, const std::string& name,
                                      const std::string& source, const std::filesystem::path& relativeTo,
                                      std::vector<Texture>& textures);
// The render block's fields over `start`.
RenderSettings readRenderBlock(const nlohmann::json& render, const std::string& source, RenderSettings start);
// objects[i].transform, named `field`: translate, rotate (degrees about x,
// then y, then z) and scale, or a matrix.
glm::dmat4 readTransformBlock(const nlohmann::json& transform, const std::string& field, const std::string& source);
// objects[i].subdivision, named `field`, onto `object`.
void readSubdivisionBlock(const nlohmann::json& subdivision, const std::string& field, const std::string& source,
                          Object& object);

// Subdivision as scene files and the command line spell it, nothing for any
// other name; kSubdivisionNames lists the spellings for error messages.
std::optional<Subdivision> subdivisionNamed(std::string_view name);
inline constexpr const char* kSubdivisionNames = "catmull-clark, none";

// Every object of `scene` takes the subdivision `name` spells, whatever its
// file chose. Any other name throws std::invalid_argument
// "<option> '<name>': expected one of: catmull-clark, none".
void overrideSubdivision(Scene& scene, const std::string& name, const std::string& option);

// The material of objects that name none: grey plastic (diffuse 0.5,
// F(0) = 0.04 Schlick, GGX alpha 0.25, height-correlated Smith).
materials::Material defaultMaterial();

// Looks at the centre of all objects' bounds from direction (1, 0.75, 1.5)
// (right, above, in front), far enough for the bounding sphere to fill 90% of
// the vertical field of view.
Camera frameBounds(const Aabb& bounds, double verticalFovDegrees = 40.0);
// A white directional key light (c_light = 1) from above the camera's left shoulder.
Light defaultKeyLight(const Camera& camera);

// The lighting of a scene that names no lights: its environment alone, the
// light it names (a key light beside it would be light nobody asked for);
// the default studio environment (studio_environment.h) where it has none.
void addDefaultLighting(Scene& scene);

// World-space box of every object's control points (which enclose the limit surface).
Aabb cageBounds(const Scene& scene);

}  // namespace facet::scene

// facet's JSON scene format; the reference is docs/scene-format.md.
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "scenes/camera_keys.h"
#include "scenes/camera_rules.h"
#include "scenes/environment_map.h"
#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/json_field.h"
#include "scenes/json_overrides.h"
#include "scenes/obj_cage.h"
#include "scenes/placement.h"
#include "scenes/scene_file.h"
#include "scenes/texture.h"
#include "scenes/value_rules.h"

namespace facet::scene {
namespace {

using detail::expandMaterialFiles;
using detail::Field;
using detail::namesMaterialFile;
using detail::readCamera;
using detail::readEnvironment;
using detail::readMaterial;
using detail::readRender;
using nlohmann::json;

Light readLight(const Field& f) {
  f.object({"type", "color", "position", "direction", "inner_cone", "outer_cone"});
  if (!f.has("type")) f.fail("a light needs a type: directional, point or spot");
  Light light;
  const std::string type = f["type"].string();
  light.type = f["type"].choice<LightType>(
      {{"directional", LightType::Directional}, {"point", LightType::Point}, {"spot", LightType::Spot}});
  if (f.has("color")) {
    light.color = f["color"].vec3();
    if (const auto rule = radianceRule(light.color)) f["color"].fail(*rule);
  }
  const bool positioned = light.type != LightType::Directional;
  const bool aimed = light.type != LightType::Point;
  if (positioned) {
    if (!f.has("position")) f.fail("a " + type + " light needs a position");
    light.position = f["position"].vec3();
  }
  if (aimed) {
    if (!f.has("direction")) f.fail("a " + type + " light needs a direction");
    light.direction = f["direction"].direction();
  }
  for (const char* key : {"position", "direction", "inner_cone", "outer_cone"}) {
    const bool allowed = std::string(key) == "position"    ? positioned
                         : std::string(key) == "direction" ? aimed
                                                           : light.type == LightType::Spot;
    if (f.has(key) && !allowed) f[key].fail("does not apply to a " + type + " light");
  }
  if (light.type == LightType::Spot) {
    if (f.has("outer_cone")) light.outerConeDegrees = f["outer_cone"].number(0.0, kMaxSpotConeDegrees);
    if (f.has("inner_cone")) light.innerConeDegrees = f["inner_cone"].number(0.0, light.outerConeDegrees);
    if (light.innerConeDegrees > light.outerConeDegrees) f.fail("inner_cone must not exceed outer_cone");
  }
  return light;
}

std::vector<Light> readLights(const Field& f) {
  if (!f.value().is_array()) f.fail("expected an array");
  std::vector<Light> lights;
  for (std::size_t i = 0; i < f.value().size(); ++i) lights.push_back(readLight(f[i]));
  return lights;
}

// An object's material that is none of the scene's named ones: a preset name
// (that preset at the default material's roughness), a material file, or
// the fields of a material.
materials::Material objectMaterial(const Field& f, const std::filesystem::path& relativeTo,
                                   std::vector<Texture>& textures) {
  if (!f.value().is_string() || namesMaterialFile(f.string())) return readMaterial(f, relativeTo, textures);
  const json preset = {{"preset", f.string()}, {"roughness", std::sqrt(defaultMaterial().alpha)}};
  return readMaterial(Field(preset, f.path(), f.source()), relativeTo, textures);
}

glm::dmat4 readTransform(const Field& f) {
  f.object({"translate", "rotate", "scale", "matrix"});
  if (f.has("matrix")) {
    if (f.has("translate") || f.has("rotate") || f.has("scale"))
      f.fail("give either matrix or translate/rotate/scale, not both");
    const Field m = f["matrix"];
    if (!m.value().is_array() || m.value().size() != 16) m.fail("expected 16 numbers, column by column");
    glm::dmat4 matrix;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) matrix[c][r] = m[std::size_t(4 * c + r)].number();
    if (matrix[0][3] != 0 || matrix[1][3] != 0 || matrix[2][3] != 0 || matrix[3][3] != 1)
      m.fail("must be affine (last row 0, 0, 0, 1)");
    // A flattening matrix leaves a surface without area and normals without a direction.
    const double determinant = glm::determinant(glm::dmat3(matrix));
    if (!std::isfinite(determinant) || determinant == 0) m.fail("must be invertible (its determinant is 0)");
    return matrix;
  }
  glm::dmat4 matrix(1.0);
  if (f.has("translate")) matrix = glm::translate(matrix, f["translate"].vec3());
  if (f.has("rotate")) {
    // Degrees about x, then y, then z (applied to the object in that order).
    const glm::dvec3 r = glm::radians(f["rotate"].vec3());
    matrix = glm::rotate(matrix, r.z, {0, 0, 1});
    matrix = glm::rotate(matrix, r.y, {0, 1, 0});
    matrix = glm::rotate(matrix, r.x, {1, 0, 0});
  }
  if (f.has("scale")) {
    const Field s = f["scale"];
    const glm::dvec3 scale = s.value().is_array() ? s.vec3() : glm::dvec3(s.number());
    if (scale.x == 0 || scale.y == 0 || scale.z == 0) s.fail("must not be zero");
    matrix = glm::scale(matrix, scale);
  }
  return matrix;
}

// A scheme by name, or an object of Catmull-Clark's settings.
void readSubdivision(const Field& f, Object& object) {
  if (f.value().is_string()) {
    const std::string name = f.string();
    const std::optional<Subdivision> subdivision = subdivisionNamed(name);
    if (!subdivision) f.fail("unknown value '" + name + "' (expected one of: " + kSubdivisionNames + ")");
    object.subdivision = *subdivision;
    return;
  }
  if (!f.value().is_object())
    f.fail(std::string("expected one of: ") + kSubdivisionNames + ", or an object of Catmull-Clark settings");
  f.object({"isolation", "end_caps"});
  object.subdivision = Subdivision::CatmullClark;
  if (f.has("isolation")) object.isolationLevel = f["isolation"].integer(1, 10);
  if (f.has("end_caps"))
    object.endCaps =
        f["end_caps"].choice<EndCapBasis>({{"gregory", EndCapBasis::Gregory}, {"bspline", EndCapBasis::BSpline}});
}

// `path`: a file in the folder the document's files are relative to.
Scene sceneFromDocument(const json& document, const std::filesystem::path& path, const std::string& source) {
  const Field root(document, "", source);
  root.object({"camera", "camera_keys", "materials", "objects", "lights", "render", "environment"});

  Scene scene;
  scene.source = source;
  scene.render.bouncesStated = false;  // unless the render block states them
  scene.render.sampling = Sampling::Chosen;
  std::map<std::string, int> materialIndex;
  if (root.has("materials")) {
    const Field materials = root["materials"];
    if (!materials.value().is_object()) materials.fail("expected an object of named materials");
    for (const auto& item : materials.value().items()) {
      if (namesMaterialFile(item.key()))
        materials[item.key().c_str()].fail("a material's name must not end in .json, which names a material file");
      materials::Material m =
          readMaterial(Field(item.value(), "materials." + item.key(), source), path, scene.textures);
      m.name = item.key();
      materialIndex[item.key()] = int(scene.materials.size());
      scene.materials.push_back(std::move(m));
    }
  }

  if (!root.has("objects")) root.fail("a scene needs objects");
  const Field objects = root["objects"];
  if (!objects.value().is_array() || objects.value().empty()) objects.fail("expected a non-empty array");
  for (std::size_t i = 0; i < objects.value().size(); ++i) {
    const Field o = objects[i];
    o.object({"name", "mesh", "material", "transform", "subdivision"});
    Object object;
    object.name = o.has("name") ? o["name"].string() : "object " + std::to_string(i);
    if (!o.has("mesh")) o.fail("an object needs a mesh (an .obj control cage, relative to the scene file)");
    const std::filesystem::path mesh = path.parent_path() / o["mesh"].string();
    if (mesh.extension() != ".obj") o["mesh"].fail("meshes are OpenSubdiv-style .obj cages");
    if (const std::optional<std::string> problem = inputFileProblem(mesh))
      o["mesh"].fail(*problem + ": " + mesh.string());
    object.cage = loadObjCage(mesh);
    if (o.has("transform")) transformCage(object.cage, readTransform(o["transform"]));

    if (!o.has("material")) {
      object.material = int(scene.materials.size());
      scene.materials.push_back(defaultMaterial());
    } else if (o["material"].value().is_string() && !namesMaterialFile(o["material"].string())) {
      const std::string name = o["material"].string();
      auto known = materialIndex.find(name);
      if (known != materialIndex.end()) {
        object.material = known->second;
      } else {
        object.material = int(scene.materials.size());
        scene.materials.push_back(objectMaterial(o["material"], path, scene.textures));
        materialIndex[name] = object.material;
      }
    } else {
      object.material = int(scene.materials.size());
      scene.materials.push_back(objectMaterial(o["material"], path, scene.textures));
    }

    if (o.has("subdivision")) readSubdivision(o["subdivision"], object);
    scene.objects.push_back(std::move(object));
  }

  if (root.has("render")) readRender(root["render"], scene.render);
  if (root.has("environment")) scene.environment = readEnvironment(root["environment"], path);
  if (bouncesContradictEnvironment(scene.render, scene.environment))
    root["render"]["bounces"].fail(kBouncesNeedOcclusionRule);
  scene.camera = root.has("camera") ? readCamera(root["camera"], Camera{}) : frameBounds(cageBounds(scene));
  if (root.has("camera_keys"))
    scene.cameraKeys =
        readCameraKeys(document["camera_keys"], scene.camera, source, [&](const json& camera, const std::string& at) {
          return readCamera({camera, at, source}, Camera{});
        });
  if (root.has("lights")) {
    scene.lights = readLights(root["lights"]);
  } else {
    addDefaultLighting(scene);
  }
  return scene;
}

}  // namespace

nlohmann::json readSceneDocument(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(source, 0, "cannot open the scene file", "check the path and permissions");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {  // syntax errors, and numbers beyond double's range
    throw InputError(source, 0, "not valid JSON", e.what());
  }
}

Scene sceneFromJson(const nlohmann::json& document, const std::filesystem::path& folder, const std::string& source) {
  return sceneFromDocument(document, folder / "", source);
}

Scene loadJsonScene(const std::filesystem::path& path, std::span<const JsonOverride> overrides) {
  const std::string source = path.string();
  json document = readSceneDocument(path);
  expandMaterialFiles(document, overrides);
  for (const JsonOverride& o : overrides) applyJsonOverride(document, o);
  try {
    return sceneFromDocument(document, path, source);
  } catch (const InputError& e) {
    // A field an override set is named with the override.
    for (const JsonOverride& o : overrides)
      if (e.source() == source && overrideConcerns(o, e.rule()))
        throw InputError(source, 0, e.rule() + " (--set " + o.text() + ")",
                         std::string(e.what()).substr(source.size() + e.rule().size() + 4));
    throw;
  }
}

Camera readCameraBlock(const nlohmann::json& camera, const std::string& source) {
  return readCamera(Field(camera, "camera", source), Camera{});
}

std::vector<Light> readLightsBlock(const nlohmann::json& lights, const std::string& source) {
  return readLights(Field(lights, "lights", source));
}

Environment readEnvironmentBlock(const nlohmann::json& environment, const std::string& source,
                                 const std::filesystem::path& relativeTo, const std::optional<Environment>& start) {
  return readEnvironment(Field(environment, "environment", source), relativeTo, start);
}

materials::Material readObjectMaterial(const nlohmann::json& material, int object, const std::string& source,
                                       const std::filesystem::path& relativeTo, std::vector<Texture>& textures) {
  const Field f(material, "objects[" + std::to_string(object) + "].material", source);
  return objectMaterial(f, relativeTo, textures);
}

materials::Material readNamedMaterial(const nlohmann::json& material, const std::string& name,
                                      const std::string& source, const std::filesystem::path& relativeTo,
                                      std::vector<Texture>& textures) {
  const Field f(material, "materials." + name, source);
  if (namesMaterialFile(name)) f.fail("a material's name must not end in .json, which names a material file");
  materials::Material m = readMaterial(f, relativeTo, textures);
  m.name = name;
  return m;
}

RenderSettings readRenderBlock(const nlohmann::json& render, const std::string& source, RenderSettings start) {
  readRender(Field(render, "render", source), start);
  return start;
}

glm::dmat4 readTransformBlock(const nlohmann::json& transform, const std::string& field, const std::string& source) {
  return readTransform(Field(transform, field, source));
}

void readSubdivisionBlock(const nlohmann::json& subdivision, const std::string& field, const std::string& source,
                          Object& object) {
  readSubdivision(Field(subdivision, field, source), object);
}

}  // namespace facet::scene

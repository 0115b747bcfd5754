// Scene::set, `--set PATH=VALUE` on a Scene: the field's block is written as
// a scene file would now hold it, the override applied to it by --set's own
// code, and the block read back by the file's reader, so that the value
// obeys the file's rules and a refusal leaves the scene as it was.
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>
#include <string>
#include <utility>

#include "api/errors.h"
#include "api/scene_blocks.h"
#include "api/scene_data.h"
#include "scenes/input_error.h"
#include "scenes/json_overrides.h"
#include "scenes/placement.h"
#include "scenes/scene_file.h"

namespace facet::v0 {
namespace {

using nlohmann::json;
using Data = std::shared_ptr<const detail::SceneData>;

// `o` applied to a document that holds `block` alone under `root`, and the block it leaves.
json overridden(const std::string& root, json block, const scene::JsonOverride& o) {
  json document = {{root, std::move(block)}};
  scene::applyJsonOverride(document, o);
  return document[root];
}

Data setRenderField(const detail::SceneData& d, const scene::JsonOverride& o) {
  const scene::RenderSettings r =
      scene::readRenderBlock(overridden("render", json::object(), o), api::kCodeSource, d.scene.render);
  if (scene::bouncesContradictEnvironment(r, d.scene.environment))
    api::refuse(api::kCodeSource, "render.bounces", scene::kBouncesNeedOcclusionRule);
  return api::changed(d, [&](detail::SceneData& c) { c.scene.render = r; });
}

Data setEnvironmentField(const detail::SceneData& d, const scene::JsonOverride& o) {
  const std::optional<scene::Environment>& now = d.scene.environment;
  const json block = now ? api::environmentBlock(*api::apiEnvironment(now), now) : json::object();
  const scene::Environment e =
      scene::readEnvironmentBlock(overridden("environment", block, o), api::kCodeSource, d.relativeTo, now);
  if (scene::bouncesContradictEnvironment(d.scene.render, e))
    api::refuse(api::kCodeSource, "render.bounces", scene::kBouncesNeedOcclusionRule);
  return api::changed(d, [&](detail::SceneData& c) { c.scene.environment = e; });
}

// materials.NAME...: the named material as the file (or an earlier set)
// wrote it, changed; every object that wears it wears the change. A new
// name adds a material that objects[N].material may then name.
Data setNamedMaterial(const detail::SceneData& d, const scene::JsonOverride& o) {
  const std::size_t end = o.path.find_first_of(".[", std::string("materials.").size());
  if (o.path.rfind("materials.", 0) != 0)
    api::refuse(api::kCodeSource, o.path, "set one material, materials.NAME, or a field of one, materials.NAME.FIELD");
  const std::string name = o.path.substr(10, end == std::string::npos ? std::string::npos : end - 10);
  const json block = overridden("materials", json(d.namedMaterials), o);
  std::vector<scene::Texture> textures = d.scene.textures;
  const materials::Material m = scene::readNamedMaterial(block[name], name, api::kCodeSource, d.relativeTo, textures);
  return api::changed(d, [&](detail::SceneData& c) {
    const bool known = c.namedMaterials.count(name) > 0;
    c.namedMaterials[name] = block[name];
    c.scene.textures = std::move(textures);
    if (!known) return;
    for (materials::Material& worn : c.scene.materials)
      if (worn.name == name) worn = m;
  });
}

// The number N of a path objects[N]..., or -1 where it has none.
int objectNumber(const std::string& path, std::size_t close) {
  if (path.rfind("objects[", 0) != 0 || close == std::string::npos || close <= 8 || close - 8 > 9) return -1;
  int object = 0;
  for (std::size_t i = 8; i < close; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(path[i]))) return -1;
    object = 10 * object + (path[i] - '0');
  }
  return object;
}

Data wearing(const detail::SceneData& d, int object, materials::Material m, std::vector<scene::Texture> textures) {
  return api::changed(d, [&](detail::SceneData& c) {
    c.scene.textures = std::move(textures);
    api::wearMaterial(c.scene, object, std::move(m));
  });
}

// objects[N].material: a named material, a preset, a file or a material's fields.
Data setObjectMaterial(const detail::SceneData& d, int object, const json& value) {
  std::vector<scene::Texture> textures = d.scene.textures;
  if (value.is_string() && d.namedMaterials.count(value.get<std::string>())) {
    const std::string name = value.get<std::string>();
    materials::Material m =
        scene::readNamedMaterial(d.namedMaterials.at(name), name, api::kCodeSource, d.relativeTo, textures);
    return wearing(d, object, std::move(m), std::move(textures));
  }
  materials::Material m = scene::readObjectMaterial(value, object, api::kCodeSource, d.relativeTo, textures);
  if (value.is_string()) m.name = std::filesystem::path(value.get<std::string>()).stem().string();
  return wearing(d, object, std::move(m), std::move(textures));
}

// objects[N].FIELD: a material, a transform, a name or a subdivision.
Data setObjectField(const detail::SceneData& d, const scene::JsonOverride& o) {
  const std::size_t close = o.path.find(']');
  const int object = objectNumber(o.path, close);
  if (object < 0 || close + 1 >= o.path.size() || o.path[close + 1] != '.')
    api::refuse(api::kCodeSource, o.path,
                "set a field of one object: objects[N].material, .transform, .name or .subdivision");
  const std::string where = o.path.substr(0, close + 1), field = o.path.substr(close + 2);
  const std::string key = field.substr(0, field.find_first_of(".["));
  const int count = int(d.scene.objects.size());
  if (object >= count)
    api::refuse(api::kCodeSource, where, "no such object (the scene has " + std::to_string(count) + ")");
  const json value = overridden("value", nullptr, {"value", o.value});
  if (key == "material") {
    if (field != "material")
      api::refuse(api::kCodeSource, o.path,
                  "give the whole material (a preset, a material file or its fields), or change a named "
                  "material with materials.NAME." +
                      field.substr(9));
    return setObjectMaterial(d, object, value);
  }
  if (key == "transform") {
    const json block =
        overridden("transform", d.transforms[std::size_t(object)], {"transform" + field.substr(9), o.value});
    return api::changed(d, [&](detail::SceneData& c) { api::placeObject(c, object, block); });
  }
  if (key == "name" && field == "name") {
    if (!value.is_string()) api::refuse(api::kCodeSource, o.path, "expected a string");
    return api::changed(d, [&](detail::SceneData& c) { c.scene.objects[std::size_t(object)].name = value; });
  }
  if (key == "subdivision") {
    scene::Object changed = d.scene.objects[std::size_t(object)];
    const json block = overridden("subdivision", nullptr, {"subdivision" + field.substr(11), o.value});
    scene::readSubdivisionBlock(block, where + ".subdivision", api::kCodeSource, changed);
    return api::changed(d, [&](detail::SceneData& c) { c.scene.objects[std::size_t(object)] = std::move(changed); });
  }
  if (key == "mesh")
    api::refuse(api::kCodeSource, o.path,
                "an object's mesh is not changed in place: remove the object and add one (removeObject, addObject)");
  api::refuse(api::kCodeSource, o.path, "set changes an object's material, transform, name and subdivision");
}

}  // namespace

void Scene::set(const std::string& path, const std::string& value) {
  data_ = api::translateErrors([&] {
    return api::readingInputs([&]() -> Data {
      const scene::JsonOverride o{path, value};
      const std::string root = path.substr(0, path.find_first_of(".["));
      const detail::SceneData& d = *data_;
      if (root == "render") return setRenderField(d, o);
      if (root == "environment") return setEnvironmentField(d, o);
      if (root == "materials") return setNamedMaterial(d, o);
      if (root == "camera") {
        const scene::Camera c =
            scene::readCameraBlock(overridden("camera", api::cameraBlock(camera()), o), api::kCodeSource);
        return api::changed(d, [&](detail::SceneData& s) { s.scene.camera = c; });
      }
      if (root == "lights") {
        std::vector<scene::Light> ls =
            scene::readLightsBlock(overridden("lights", api::lightsBlock(lights()), o), api::kCodeSource);
        return api::changed(d, [&](detail::SceneData& s) { s.scene.lights = std::move(ls); });
      }
      if (root == "objects") return setObjectField(d, o);
      api::refuse(api::kCodeSource, path,
                  "set changes render, camera, lights, environment, materials.NAME and objects[N]");
    });
  });
}

}  // namespace facet::v0

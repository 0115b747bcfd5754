// Scenes from files and JSON documents through the engine's loaders, and
// from code through the same rules the JSON loader applies (its own readers
// for the camera, lights, environment and transforms), each error naming
// the field.
#include <cmath>
#include <filesystem>
#include <string>

#include "api/errors.h"
#include "api/material.h"
#include "api/scene_blocks.h"
#include "api/scene_data.h"
#include "api/scene_objects.h"
#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/scene_file.h"

namespace facet::v0 {
namespace {

scene::Scene engineScene(const SceneDescription& d) {
  scene::Scene s;
  s.source = api::kCodeSource;
  s.render.bouncesStated = false;  // RenderSettings::bounces and spp state them
  s.render.sampling = scene::Sampling::Chosen;
  for (std::size_t i = 0; i < d.materials.size(); ++i)
    s.materials.push_back(api::toEngineMaterial(d.materials[i], "materials[" + std::to_string(i) + "]"));
  if (s.materials.empty()) s.materials.push_back(scene::defaultMaterial());
  if (d.objects.empty()) throw scene::InputError(api::kCodeSource, 0, "objects", "a scene needs at least one object");
  for (std::size_t i = 0; i < d.objects.size(); ++i)
    s.objects.push_back(api::engineObject(d.objects[i], int(i), int(s.materials.size())));
  s.camera = scene::frameBounds(scene::cageBounds(s));
  s.render.width = int(api::checkedRange(d.width, 1, 16384, "width"));
  s.render.height = int(api::checkedRange(d.height, 1, 16384, "height"));
  return s;
}

std::filesystem::path workingFolder() { return std::filesystem::current_path() / ""; }

// Camera, lights and environment go through the scene's own setters, which
// read them as a scene file's blocks; the objects keep the transforms they
// were described with.
Scene described(const SceneDescription& d) {
  Scene scene = api::sceneOf(engineScene(d), workingFolder());
  if (d.camera) scene.setCamera(*d.camera);
  scene.setLights(d.lights);
  scene.setEnvironment(d.environment);
  auto data = std::make_shared<detail::SceneData>(scene.data());
  if (d.lights.empty()) scene::addDefaultLighting(data->scene);
  for (std::size_t i = 0; i < d.objects.size(); ++i) data->transforms[i] = api::transformBlock(d.objects[i].transform);
  return Scene(std::move(data));
}

bool isJsonScene(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".json";
}

}  // namespace

Scene::Scene(std::shared_ptr<const detail::SceneData> data) : data_(std::move(data)) {
  if (!data_) throw Error(ErrorKind::BadInput, "Scene: no scene data; make a Scene with loadScene or buildScene");
}

int Scene::width() const { return data_->scene.render.width; }
int Scene::height() const { return data_->scene.render.height; }
int Scene::objectCount() const { return int(data_->scene.objects.size()); }

Scene loadScene(const std::string& path) { return loadScene(path, std::string()); }

Scene loadScene(const std::string& path, const std::string& variant) {
  return api::translateErrors([&] {
    const scene::InputFileLog read;
    if (!isJsonScene(path) || !variant.empty()) {  // a JSON scene has no variants: the loader says so
      scene::Scene s = scene::loadScene(path, {}, variant);
      return api::sceneOf(std::move(s), path, nullptr, read.files());
    }
    // Read once: the document its edits start from is the one it was loaded from.
    scene::checkInputFile(path, "the scene");
    const nlohmann::json document = scene::readSceneDocument(path);
    scene::Scene s = scene::sceneFromJson(document, std::filesystem::path(path).parent_path(), path);
    return api::sceneOf(std::move(s), path, document, read.files());
  });
}

Scene buildScene(const SceneDescription& description) {
  return api::translateErrors([&] { return described(description); });
}

Scene sceneFromJson(const std::string& json, const std::string& folder) {
  return api::translateErrors([&] {
    nlohmann::json document;
    try {
      document = nlohmann::json::parse(json);
    } catch (const nlohmann::json::exception& e) {
      throw scene::InputError(api::kCodeSource, 0, "not valid JSON", e.what());
    }
    const scene::InputFileLog read;
    scene::Scene s = scene::sceneFromJson(document, folder, api::kCodeSource);
    return api::sceneOf(std::move(s), std::filesystem::path(folder) / "", document, read.files());
  });
}

}  // namespace facet::v0

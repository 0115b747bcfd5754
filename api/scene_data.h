// What a public facet::Scene holds: the engine's validated scene, and what
// its edits need to obey the scene file's rules.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facet/scene.h"
#include "scenes/input_file.h"
#include "scenes/scene.h"

namespace facet::v0::detail {

struct SceneData {
  scene::Scene scene;
  // A file in the folder that the files an edit names are relative to: the
  // scene file, or the working folder's "" for a scene built in code.
  std::filesystem::path relativeTo;
  // The file's materials block as written, by name: what
  // set("materials.NAME...") changes, as --set changes the file.
  std::map<std::string, nlohmann::json> namedMaterials;
  // The files it was read from, and those its edits read: what no output
  // written from it may replace.
  std::vector<std::filesystem::path> inputs;
  // Each object's transform block as its file wrote it (an empty object
  // where it has none), in the objects' order: what its cage was placed by.
  std::vector<nlohmann::json> transforms;
};

}  // namespace facet::v0::detail

namespace facet::api {

// What errors name in place of a file for a scene built or changed in code.
inline constexpr const char* kCodeSource = "scene";

// `scene` as a Scene; `document`: the JSON it was read from, whose
// materials block and objects' transforms its edits start from.
v0::Scene sceneOf(scene::Scene scene, std::filesystem::path relativeTo, const nlohmann::json& document = nullptr,
                  std::vector<std::filesystem::path> inputs = {});

// `edit`, which returns the changed data, run with an InputFileLog open:
// the files it read join the changed data's inputs.
template <class Edit>
std::shared_ptr<const v0::detail::SceneData> readingInputs(Edit&& edit) {
  const scene::InputFileLog log;
  std::shared_ptr<const v0::detail::SceneData> result = edit();
  if (log.files().empty()) return result;
  auto withInputs = std::make_shared<v0::detail::SceneData>(*result);
  for (const std::filesystem::path& file : log.files())
    if (std::find(withInputs->inputs.begin(), withInputs->inputs.end(), file) == withInputs->inputs.end())
      withInputs->inputs.push_back(file);
  return withInputs;
}

// The object's material becomes `material`: in its place when no other
// object shares it, so that the scene's materials stay as a file that names
// this material would have them.
void wearMaterial(scene::Scene& scene, int object, materials::Material material);

// The object placed by the transform block `transform` in place of the one
// it had; throws InputError for a transform the file's rules refuse.
void placeObject(v0::detail::SceneData& data, int object, const nlohmann::json& transform);

// `data` with `change` applied to a copy: copies of the Scene made before
// keep what they had.
template <class Change>
std::shared_ptr<const v0::detail::SceneData> changed(const v0::detail::SceneData& data, Change&& change) {
  auto copy = std::make_shared<v0::detail::SceneData>(data);
  change(*copy);
  return copy;
}

}  // namespace facet::api

#include "scenes/camera_keys.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "scenes/input_error.h"

namespace facet::scene {

std::vector<CameraKey> readCameraKeys(
    const nlohmann::json& keys, const Camera& sceneCamera, const std::string& source,
    const std::function<Camera(const nlohmann::json&, const std::string&)>& readCamera) {
  if (!keys.is_array() || keys.empty())
    throw InputError(source, 0, "camera_keys", "expected a non-empty array of {\"frame\", \"eye\", ...}");
  std::vector<CameraKey> result;
  Camera previous = sceneCamera;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string path = "camera_keys[" + std::to_string(i) + "]";
    const nlohmann::json& key = keys[i];
    if (!key.is_object()) throw InputError(source, 0, path, "expected an object");
    if (!key.contains("frame")) throw InputError(source, 0, path, "a key needs a \"frame\"");
    const nlohmann::json& frame = key["frame"];
    const double number = frame.is_number() ? frame.get<double>() : NAN;
    if (!(number == std::floor(number) && std::abs(number) <= std::numeric_limits<int>::max()))
      throw InputError(source, 0, path + ".frame", "expected a whole number");
    if (!result.empty() && int(number) <= result.back().frame)
      throw InputError(source, 0, path + ".frame", "frames must increase from key to key");
    // The fields this key leaves out come from the key before; the scene's
    // camera block then checks the whole camera.
    nlohmann::json camera = {{"eye", {previous.eye.x, previous.eye.y, previous.eye.z}},
                             {"target", {previous.target.x, previous.target.y, previous.target.z}},
                             {"up", {previous.up.x, previous.up.y, previous.up.z}},
                             {"fov", previous.verticalFovDegrees}};
    for (const auto& [name, value] : key.items())
      if (name != "frame") camera[name] = value;
    previous = readCamera(camera, path);
    result.push_back({int(number), previous});
  }
  return result;
}

}  // namespace facet::scene

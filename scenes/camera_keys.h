// Camera keyframes of a JSON scene, "camera_keys" (docs/scene-format.md):
// an array of {"frame", "eye", "target", "up", "fov"}, frames increasing,
// each field but "frame" defaulting to the key before (the scene's camera
// for the first).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace facet::scene {

// `readCamera(value, path)` reads one camera block with the scene's rules;
// throws InputError "<source>: camera_keys[i].<field>: <rule>".
std::vector<CameraKey> readCameraKeys(
    const nlohmann::json& keys, const Camera& sceneCamera, const std::string& source,
    const std::function<Camera(const nlohmann::json&, const std::string&)>& readCamera);

}  // namespace facet::scene

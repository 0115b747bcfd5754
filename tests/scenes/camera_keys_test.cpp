// "camera_keys" in JSON scenes: defaults from the key before, frames that
// increase, and the camera block's own rules for each key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "scenes/camera_keys.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"

namespace facet::scene {
namespace {

using ::testing::HasSubstr;

// Stands in for the scene's camera reader: takes eye, target, up and fov as given.
Camera plainCamera(const nlohmann::json& j, const std::string&) {
  Camera c;
  c.eye = {j["eye"][0], j["eye"][1], j["eye"][2]};
  c.target = {j["target"][0], j["target"][1], j["target"][2]};
  c.up = {j["up"][0], j["up"][1], j["up"][2]};
  c.verticalFovDegrees = j["fov"];
  return c;
}

std::string errorOf(const char* keys) {
  try {
    readCameraKeys(nlohmann::json::parse(keys), Camera{}, "scene.json", plainCamera);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CameraKeys, FieldsAKeyLeavesOutComeFromTheKeyBefore) {
  Camera still;
  still.eye = {0, 1, 9};
  const auto keys = readCameraKeys(nlohmann::json::parse(R"([{"frame": 0, "fov": 30},
                                                            {"frame": 10, "eye": [4, 0, 0]}])"),
                                   still, "scene.json", plainCamera);
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].camera.eye, glm::dvec3(0, 1, 9));
  EXPECT_EQ(keys[0].camera.verticalFovDegrees, 30);
  EXPECT_EQ(keys[1].frame, 10);
  EXPECT_EQ(keys[1].camera.eye, glm::dvec3(4, 0, 0));
  EXPECT_EQ(keys[1].camera.verticalFovDegrees, 30);
}

TEST(CameraKeys, ErrorsNameTheKeyAndTheRule) {
  EXPECT_THAT(errorOf("[]"), HasSubstr("scene.json: camera_keys: expected a non-empty array"));
  EXPECT_THAT(errorOf(R"([{"eye": [1, 2, 3]}])"), HasSubstr("camera_keys[0]: a key needs a \"frame\""));
  EXPECT_THAT(errorOf(R"([{"frame": 1.5}])"), HasSubstr("camera_keys[0].frame: expected a whole number"));
  EXPECT_THAT(errorOf(R"([{"frame": 3}, {"frame": 3}])"),
              HasSubstr("camera_keys[1].frame: frames must increase from key to key"));
}

class CameraKeysInScenes : public testing::TempDirTest {};

TEST_F(CameraKeysInScenes, EachKeyFollowsTheCameraBlocksRules) {
  std::filesystem::copy_file(std::filesystem::path(FACET_EXAMPLES_DIR) / "superball.obj", dir_ / "ball.obj");
  std::ofstream(dir_ / "keys.json") << R"({"objects": [{"mesh": "ball.obj"}], "camera": {"eye": [0, 0, 6]},
      "camera_keys": [{"frame": 0}, {"frame": 8, "eye": [6, 0, 0]}]})";
  const Scene scene = loadScene(dir_ / "keys.json");
  ASSERT_EQ(scene.cameraKeys.size(), 2u);
  EXPECT_EQ(scene.cameraKeys[0].camera.eye, glm::dvec3(0, 0, 6));
  EXPECT_EQ(scene.cameraKeys[1].camera.eye, glm::dvec3(6, 0, 0));

  std::ofstream(dir_ / "bad.json")
      << R"({"objects": [{"mesh": "ball.obj"}], "camera_keys": [{"frame": 0, "fov": 500}]})";
  try {
    loadScene(dir_ / "bad.json");
    ADD_FAILURE() << "a fov of 500 degrees was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("camera_keys[0].fov"));
  }
}

}  // namespace
}  // namespace facet::scene

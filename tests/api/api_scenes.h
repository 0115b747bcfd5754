// What the public API's scene tests share: small CPU renders on one
// Renderer, image comparison, scene files written for a test, and the
// message of a refused change.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <facet/facet.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace facet::testing {

inline const std::string kCube = std::string(FACET_CAGE_DIR) + "/cube.obj";
inline const std::string kCourtyard = std::string(FACET_ENVIRONMENTS_DIR) + "/courtyard_256x128.hdr";

// 24 x 24, one sample per pixel, on the CPU reference: the same image each time.
inline facet::RenderSettings small() {
  facet::RenderSettings settings;
  settings.backend = facet::Backend::Cpu;
  settings.width = settings.height = 24;
  settings.spp = 1;
  return settings;
}

inline facet::Renderer& renderer() {
  static facet::Renderer shared;
  return shared;
}

inline facet::Image render(const facet::Scene& scene) { return renderer().render(scene, small()).image; }

// Mean beauty (r, g, b) over the pixels the object covers.
inline facet::Vec3 meanCovered(const facet::Image& image) {
  const std::vector<float>& rgba = image.aov("beauty").values;
  facet::Vec3 sum;
  int covered = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    if (rgba[i + 3] == 0) continue;
    sum.x += rgba[i], sum.y += rgba[i + 1], sum.z += rgba[i + 2];
    ++covered;
  }
  EXPECT_GT(covered, 24 * 24 / 8);
  return {sum.x / covered, sum.y / covered, sum.z / covered};
}

inline void expectSameImage(const facet::Image& a, const facet::Image& b) {
  ASSERT_EQ(a.aovs.size(), b.aovs.size());
  for (const auto& [name, aov] : a.aovs) EXPECT_EQ(aov.values, b.aov(name).values) << name;
  EXPECT_EQ(a.ids, b.ids);
}

// A folder of this process's own, removed when the process ends.
class SceneFolder {
 public:
  SceneFolder() : path_(std::filesystem::temp_directory_path() / ("facet_api_scenes_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~SceneFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  SceneFolder(const SceneFolder&) = delete;
  SceneFolder& operator=(const SceneFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// A file in the process's scene folder.
inline std::filesystem::path writeScene(const std::string& name, const std::string& json) {
  static const SceneFolder folder;
  const std::filesystem::path file = folder.path() / name;
  std::ofstream(file) << json;
  return file;
}

// The message after "SOURCE: ", which names the field and the rule.
inline std::string fieldAndRule(const std::string& message, const std::string& source) {
  EXPECT_EQ(message.rfind(source + ": ", 0), 0u) << message;
  return message.substr(source.size() + 2);
}

template <class F>
std::string errorOf(F&& change) {
  try {
    change();
  } catch (const facet::Error& e) {
    EXPECT_EQ(e.kind(), facet::ErrorKind::BadInput);
    return e.what();
  }
  return "no error";
}

}  // namespace facet::testing

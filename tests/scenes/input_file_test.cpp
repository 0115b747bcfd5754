// The files a load depends on, as InputFileLog gathers them: a scene file,
// the material files it names and extends, its cage, a texture and an
// environment map, each once; a file that fails its check too; nested logs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cstdint>
#include <fstream>
#include <vector>

#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
using ::testing::Contains;
using ::testing::UnorderedElementsAre;

const fs::path kEnvironments = FACET_ENVIRONMENTS_DIR;

class InputFiles : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    fs::copy_file(fs::path(FACET_EXAMPLES_DIR) / "superball.obj", dir_ / "ball.obj");
    fs::create_directories(dir_ / "lib");
    const std::vector<std::uint8_t> grey(4 * 2 * 3, 128);
    ASSERT_TRUE(stbi_write_png((dir_ / "lib" / "albedo.png").c_str(), 4, 2, 3, grey.data(), 4 * 3));
    write("lib/base.json", R"({"roughness": 0.3})");
    write("lib/red.json", R"({"extends": "base.json", "diffuse_texture": "albedo.png"})");
  }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
};

TEST_F(InputFiles, ASceneDependsOnEveryFileItsLoadersRead) {
  const fs::path environment = kEnvironments / "courtyard_256x128.hdr";
  const fs::path scene = write("scene.json", R"({"objects": [
      {"mesh": "ball.obj", "material": "lib/red.json"},
      {"mesh": "ball.obj", "material": {"extends": "lib/red.json", "roughness": 0.5}}],
    "environment": {"file": ")" + environment.string() +
                                                 R"("}})");
  InputFileLog log;
  loadScene(scene);
  std::vector<fs::path> files;
  for (const fs::path& file : log.files()) files.push_back(file.lexically_normal());
  EXPECT_THAT(files,
              UnorderedElementsAre(scene, dir_ / "ball.obj", dir_ / "lib" / "red.json", dir_ / "lib" / "base.json",
                                   dir_ / "lib" / "albedo.png", environment.lexically_normal()));
}

TEST_F(InputFiles, AFileThatFailsItsCheckIsAmongThem) {
  // Watching a missing file lets `facet render --watch` render once it appears.
  const fs::path scene = write("scene.json", R"({"objects": [{"mesh": "ball.obj", "material": "lib/absent.json"}]})");
  InputFileLog log;
  EXPECT_THROW(loadScene(scene), InputError);
  std::vector<fs::path> files;
  for (const fs::path& file : log.files()) files.push_back(file.lexically_normal());
  EXPECT_THAT(files, Contains(dir_ / "lib" / "absent.json"));
}

TEST_F(InputFiles, LogsNestAndEndWithTheirScope) {
  InputFileLog outer;
  {
    InputFileLog inner;
    loadScene(dir_ / "ball.obj");
    EXPECT_THAT(inner.files(), UnorderedElementsAre(dir_ / "ball.obj"));
  }
  EXPECT_THAT(outer.files(), UnorderedElementsAre(dir_ / "ball.obj"));
}

}  // namespace
}  // namespace facet::scene

// writeExr and writePng (api/output.cpp) write what `facet render` writes:
// the same scene and settings give the same EXR and PNG, byte for byte, and
// bad images and settings are refused with nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <facet/facet.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string refusalOf(const std::function<void()>& work) {
  try {
    work();
  } catch (const facet::Error& e) {
    return e.what();
  }
  return "no error";
}

class ApiOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("facet_api_output_" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

const std::string kScene = std::string(FACET_EXAMPLES_DIR) + "/gold_cube.gltf";

facet::RenderSettings smallOnCpu() {
  facet::RenderSettings settings;
  settings.backend = facet::Backend::Cpu;
  settings.width = 24;
  settings.height = 16;
  return settings;
}

TEST_F(ApiOutput, TheApiWritesTheCommandLinesBytes) {
  const fs::path cliExr = folder_ / "cli.exr", cliPng = folder_ / "cli.png";
  const std::string command = std::string(FACET_BINARY) + " render " + kScene + " -o " + cliExr.string() + " --png " +
                              cliPng.string() + " --size 24x16 --backend cpu --exposure 1 --tonemap aces --quiet";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;

  const facet::Scene scene = facet::loadScene(kScene);
  facet::Renderer renderer;
  const facet::RenderResult result = renderer.render(scene, smallOnCpu());
  const fs::path apiExr = folder_ / "api.exr", apiPng = folder_ / "api.png";
  facet::writeExr(apiExr.string(), result, scene, smallOnCpu());
  facet::PngSettings png;
  png.exposure = 1;
  png.toneCurve = facet::ToneCurve::Aces;
  facet::writePng(apiPng.string(), result.image, png);

  EXPECT_FALSE(bytesOf(cliExr).empty());
  EXPECT_EQ(bytesOf(apiExr), bytesOf(cliExr)) << "the EXRs differ";
  EXPECT_EQ(bytesOf(apiPng), bytesOf(cliPng)) << "the PNGs differ";
}

TEST_F(ApiOutput, BadImagesAndSettingsAreRefusedWithNothingWritten) {
  const facet::Scene scene = facet::loadScene(kScene);
  facet::Renderer renderer;
  facet::RenderResult result = renderer.render(scene, smallOnCpu());
  const auto refused = [&](auto write, facet::ErrorKind kind, const std::string& expected) {
    try {
      write();
      ADD_FAILURE() << "nothing refused; expected " << expected;
    } catch (const facet::Error& e) {
      EXPECT_EQ(e.kind(), kind) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(folder_)) << "a file was written";
  };
  const std::string exr = (folder_ / "out.exr").string(), png = (folder_ / "out.png").string();
  refused([&] { facet::writeExr(png, result, scene, smallOnCpu()); }, facet::ErrorKind::OutputFailed, ".exr");
  refused([&] { facet::writeExr(exr, result, scene, {}); }, facet::ErrorKind::BadInput,
          "24 x 16 is not the 512 x 512 the scene and settings render");
  facet::PngSettings dark;
  dark.exposure = std::nan("");
  refused([&] { facet::writePng(png, result.image, dark); }, facet::ErrorKind::BadInput, "exposure: expected a finite");
  facet::PngSettings negative;
  negative.background = facet::Vec3{0.1, -1, 0};
  refused([&] { facet::writePng(png, result.image, negative); }, facet::ErrorKind::BadInput, "background");
  result.image.aovs["depth"].values.pop_back();
  refused([&] { facet::writePng(png, result.image); }, facet::ErrorKind::BadInput,
          "AOV 'depth': must hold 24 x 16 x 1 values, has 383 in 1 channels");
  result.image.aovs["depth"].values.push_back(0);
  result.image.aovs.erase("uv");
  refused([&] { facet::writeExr(exr, result, scene, smallOnCpu()); }, facet::ErrorKind::BadInput, "no AOV named 'uv'");
}

// As the command line writes -o and --png: both replaced, or neither where
// either cannot be written.
TEST_F(ApiOutput, BothFilesAreReplacedTogetherOrNeither) {
  const facet::Scene scene = facet::loadScene(kScene);
  facet::Renderer renderer;
  const facet::RenderResult result = renderer.render(scene, smallOnCpu());
  const fs::path exr = folder_ / "keep.exr", png = folder_ / "keep.png";
  std::ofstream(exr) << "an earlier EXR";
  std::ofstream(png) << "an earlier PNG";
  const auto refused = [&](const fs::path& pngPath, const std::string& expected) {
    try {
      facet::writeExrAndPng(exr.string(), pngPath.string(), result, scene, smallOnCpu());
      ADD_FAILURE() << "nothing refused; expected " << expected;
    } catch (const facet::Error& e) {
      EXPECT_EQ(e.kind(), facet::ErrorKind::OutputFailed) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    EXPECT_EQ(bytesOf(exr), "an earlier EXR") << "the EXR was replaced although the PNG could not be written";
    EXPECT_EQ(bytesOf(png), "an earlier PNG");
  };
  refused(folder_ / "no_such_folder" / "keep.png", "pngPath");
  fs::create_hard_link(exr, folder_ / "link.png");
  refused(folder_ / "link.png", "names the same file as exrPath");
  refused(folder_ / "keep.jpg", ".png");

  facet::writeExrAndPng(exr.string(), png.string(), result, scene, smallOnCpu());
  const fs::path alone = folder_ / "alone.exr", alonePng = folder_ / "alone.png";
  facet::writeExr(alone.string(), result, scene, smallOnCpu());
  facet::writePng(alonePng.string(), result.image);
  EXPECT_EQ(bytesOf(exr), bytesOf(alone));
  EXPECT_EQ(bytesOf(png), bytesOf(alonePng));
}

TEST_F(ApiOutput, AnOutputNeverReplacesAFileTheSceneReads) {
  // An environment map the scene reads, and one that a later edit reads.
  const fs::path map = folder_ / "map.exr", later = folder_ / "later.exr";
  fs::copy_file(std::string(FACET_ENVIRONMENTS_DIR) + "/studio.exr", map);
  fs::copy_file(std::string(FACET_ENVIRONMENTS_DIR) + "/studio.exr", later);
  const fs::path file = folder_ / "scene.json";
  std::ofstream(file) << R"({"objects": [{"mesh": ")" << FACET_CAGE_DIR << R"(/cube.obj"}],
                             "environment": {"file": "map.exr"}})";
  facet::Scene scene = facet::loadScene(file.string());
  scene.set("environment.file", "later.exr");
  facet::Renderer renderer;
  const facet::RenderResult result = renderer.render(scene, smallOnCpu());
  const std::string original = bytesOf(map);
  for (const fs::path& input : {map, later}) {
    try {
      facet::writeExr(input.string(), result, scene, smallOnCpu());
      ADD_FAILURE() << "an input was replaced: " << input;
    } catch (const facet::Error& e) {
      EXPECT_EQ(e.kind(), facet::ErrorKind::OutputFailed);
      EXPECT_NE(std::string(e.what()).find("which this command reads: an output never replaces an input"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(bytesOf(map), original);
  // The scene file under another name is still the scene file; a copy of it is not.
  fs::create_hard_link(file, folder_ / "scene_link.png");
  const std::string linked = bytesOf(file);
  EXPECT_NE(refusalOf([&] {
              facet::writePng((folder_ / "scene_link.png").string(), result.image, scene);
            }).find("an output never replaces an input"),
            std::string::npos);
  EXPECT_EQ(bytesOf(file), linked);
  fs::copy_file(file, folder_ / "scene_copy.png");
  facet::writePng((folder_ / "scene_copy.png").string(), result.image, scene);
}

}  // namespace

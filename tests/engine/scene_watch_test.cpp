// A watched scene on the CPU reference: its first picture is written pass
// by pass; an update renders again only where a file the load read has
// changed, and then shows the change; a later load that fails on bad input
// is reported and keeps the last picture, where the first one's propagates.
// Changes are made by content and a moved modification time, so no test
// waits on the clock.
#include "engine/scene_watch.h"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/input_file.h"
#include "tests/support/blob_scene.h"
#include "tests/support/environment_maps.h"
#include "tests/support/temp_dir.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

class SceneWatchTest : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    albedoFile_ = dir_ / "albedo.txt";
    setAlbedo("0.2");
  }

  // A change a watch must see however coarse the file system's clock:
  // new content and a modification time moved on by a second.
  void setAlbedo(const std::string& text) {
    const bool existed = fs::exists(albedoFile_);
    const fs::file_time_type before = existed ? fs::last_write_time(albedoFile_) : fs::file_time_type();
    std::ofstream(albedoFile_) << text;
    if (existed) fs::last_write_time(albedoFile_, before + std::chrono::seconds(1));
  }

  // The blob under a white sky, its albedo read from the file; "bad" is bad input.
  WatchedScene watched() {
    WatchedScene w;
    w.load = [this] {
      scene::checkInputFile(albedoFile_, "albedo");
      std::string text;
      std::ifstream(albedoFile_) >> text;
      if (text == "bad") throw std::invalid_argument(albedoFile_.string() + ": not a number");
      return testing::blobUnder(testing::lambertian(std::stod(text)),
                                 std::make_shared<const scene::EnvironmentMap>(
                                     ibl::testing::mapOf(16, 8, [](glm::dvec3) { return glm::dvec3(1.0); })),
                                 8);
    };
    w.write = [this](const scene::Scene&, const Image& image, int passes, int samples) {
      writes_.push_back({passes, samples, image.beauty.at(image.index(4, 4)).x});
    };
    return w;
  }

  struct Written {
    int passes, samples;
    float centre;  // the blob's middle pixel, red
  };
  fs::path albedoFile_;
  std::vector<Written> writes_;
};

WatchSettings cpuSettings(int passes) {
  WatchSettings s;
  s.backend = Backend::Cpu;
  s.passes = passes;
  return s;
}

TEST_F(SceneWatchTest, RendersAgainOnlyWhenAWatchedFileChanges) {
  Renderer renderer;
  std::vector<WatchPicture> pictures;
  WatchEvents events;
  events.picture = [&](const WatchPicture& p) { pictures.push_back(p); };
  SceneWatch watch(renderer, watched(), cpuSettings(2), events);
  watch.render();
  ASSERT_EQ(writes_.size(), 2u) << "each pass is written";
  EXPECT_EQ(writes_[0].passes, 1);
  EXPECT_EQ(writes_[1].passes, 2);
  EXPECT_GT(writes_[1].samples, writes_[0].samples);
  ASSERT_EQ(pictures.size(), 1u);
  EXPECT_EQ(pictures[0].change, 0);
  EXPECT_TRUE(pictures[0].rendered);
  ASSERT_EQ(pictures[0].files.size(), 2u) << "the files the load read: the albedo's and the cage";
  EXPECT_EQ(pictures[0].files[0], albedoFile_);

  EXPECT_TRUE(watch.changedFiles().empty());
  EXPECT_FALSE(watch.update()) << "nothing changed";
  EXPECT_EQ(writes_.size(), 2u);

  setAlbedo("0.8");
  ASSERT_EQ(watch.changedFiles(), std::vector<fs::path>{albedoFile_});
  EXPECT_TRUE(watch.update());
  ASSERT_EQ(writes_.size(), 4u);
  EXPECT_EQ(writes_[2].passes, 1) << "a change starts the picture anew";
  EXPECT_GT(writes_[2].centre, 2.0f * writes_[0].centre) << "the new albedo is seen";
  ASSERT_EQ(pictures.size(), 2u);
  EXPECT_EQ(pictures[1].change, 1);
  EXPECT_EQ(pictures[1].files, std::vector<fs::path>{albedoFile_}) << "the files that changed";
  EXPECT_FALSE(watch.update()) << "a change is handled once";
}

TEST_F(SceneWatchTest, ALaterBadLoadKeepsTheLastPicture) {
  Renderer renderer;
  std::vector<WatchPicture> pictures;
  int badInputs = 0;
  WatchEvents events;
  events.picture = [&](const WatchPicture& p) { pictures.push_back(p); };
  events.badInput = [&](const std::exception_ptr&) { ++badInputs; };
  SceneWatch watch(renderer, watched(), cpuSettings(1), events);
  watch.render();
  setAlbedo("bad");
  EXPECT_TRUE(watch.update());
  EXPECT_EQ(badInputs, 1);
  EXPECT_EQ(writes_.size(), 1u) << "no picture of a scene that did not load";
  ASSERT_EQ(pictures.size(), 2u);
  EXPECT_FALSE(pictures[1].rendered);
  setAlbedo("0.5");
  EXPECT_TRUE(watch.update()) << "the file is still watched";
  EXPECT_EQ(writes_.size(), 2u);
}

TEST_F(SceneWatchTest, TheFirstPicturesBadInputPropagates) {
  setAlbedo("bad");
  Renderer renderer;
  SceneWatch watch(renderer, watched(), cpuSettings(1), {});
  EXPECT_THROW(watch.render(), std::invalid_argument);
}

TEST_F(SceneWatchTest, AStopRequestedEndsTheWatchBeforeItRenders) {
  Renderer renderer;
  WatchEvents events;
  events.stopRequested = [] { return true; };
  SceneWatch watch(renderer, watched(), cpuSettings(4), events);
  watch.run();
  EXPECT_TRUE(writes_.empty());
}

}  // namespace
}  // namespace facet

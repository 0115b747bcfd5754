// A watched scene through the public API (api/watch.cpp): each pass reaches
// the caller, a change to the file renders the changed scene, a glTF file is
// watched in the material variant named, a refused load goes to onBadInput
// (or ends the watch, thrown), and the caller stops it.
#include <gtest/gtest.h>

#include <facet/facet.h>

#include <string>
#include <vector>

#include "api_scenes.h"

namespace {

using namespace facet::testing;

std::string watchedScene(double fov) {
  return R"({"camera": {"eye": [2.5, 2, 3], "target": [0, 0, 0], "fov": )" + std::to_string(fov) +
         R"(}, "objects": [{"mesh": ")" + kCube + R"("}]})";
}

facet::WatchSettings quickWatch(int passes, int changes) {
  facet::WatchSettings w;
  w.render = small();
  w.passes = passes;
  w.changes = changes;
  return w;
}

TEST(ApiWatch, AChangeToTheFileRendersTheChangedScene) {
  const std::string file = writeScene("watched.json", watchedScene(40)).string();
  std::vector<facet::WatchPass> seen;
  renderer().watch(
      file,
      [&](const facet::WatchPass& pass) {
        seen.push_back(pass);
        if (pass.picture == 0 && pass.passes == 2) writeScene("watched.json", watchedScene(25.5));
        return true;
      },
      quickWatch(2, 1));
  ASSERT_GE(seen.size(), 3u);
  EXPECT_EQ(seen.front().picture, 0);
  EXPECT_EQ(seen.front().passes, 1);
  EXPECT_EQ(seen.back().picture, 1);
  EXPECT_EQ(seen.back().passes, 2);
  const facet::WatchPass& changed = seen[2];
  ASSERT_EQ(changed.picture, 1);
  ASSERT_EQ(changed.passes, 1);
  expectSameImage(changed.image, render(facet::loadScene(file)));
}

TEST(ApiWatch, AGltfIsWatchedInTheMaterialVariantNamed) {
  // A triangle in material "red", which its variant "blue" maps to "blue", each of its own colour.
  const std::string file = std::string(FACET_TEST_DATA_DIR) + "/variant_triangle.gltf";
  std::vector<facet::WatchPass> seen;
  facet::WatchSettings blue = quickWatch(1, 0);
  blue.variant = "blue";
  renderer().watch(
      file,
      [&](const facet::WatchPass& pass) {
        seen.push_back(pass);
        return false;
      },
      blue);
  ASSERT_EQ(seen.size(), 1u);
  expectSameImage(seen[0].image, render(facet::loadScene(file, "blue")));
  EXPECT_NE(render(facet::loadScene(file, "blue")).aov("beauty").values,
            render(facet::loadScene(file)).aov("beauty").values);
}

TEST(ApiWatch, ARefusedLoadGoesToOnBadInputAndTheWatchGoesOn) {
  const std::string file = writeScene("refused.json", watchedScene(40)).string();
  std::vector<std::string> refusals;
  int pictures = 0;
  renderer().watch(
      file,
      [&](const facet::WatchPass& pass) {
        pictures = pass.picture + 1;
        if (pass.picture == 0) writeScene("refused.json", "{\"objects\": [");
        return true;
      },
      quickWatch(1, 2),
      [&](const facet::Error& e) {
        refusals.push_back(e.what());
        writeScene("refused.json", watchedScene(30));
        return true;
      });
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_EQ(refusals[0].rfind(file + ": not valid JSON", 0), 0u) << refusals[0];
  EXPECT_EQ(pictures, 2) << "the fixed file renders";
}

TEST(ApiWatch, WithoutOnBadInputARefusedLoadEndsTheWatch) {
  const std::string file = writeScene("ends.json", watchedScene(40)).string();
  const std::string refused = errorOf([&] {
    renderer().watch(
        file,
        [&](const facet::WatchPass&) {
          writeScene("ends.json", "{\"objects\": [");
          return true;
        },
        quickWatch(1, 0));
  });
  EXPECT_EQ(refused.rfind(file + ": not valid JSON", 0), 0u) << refused;
}

TEST(ApiWatch, TheCallerStopsItAndSettingsAreChecked) {
  const std::string file = writeScene("stopped.json", watchedScene(40)).string();
  int passes = 0;
  renderer().watch(
      file,
      [&](const facet::WatchPass&) {
        ++passes;
        return false;
      },
      quickWatch(4, 0));
  EXPECT_EQ(passes, 1);
  EXPECT_EQ(errorOf([&] {
              renderer().watch(
                  file, [](const facet::WatchPass&) { return true; }, quickWatch(0, 0));
            }),
            "watch settings: passes: expected passes in [1, 4096]");
}

}  // namespace

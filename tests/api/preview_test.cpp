// The preview stage through the public API (api/preview.cpp): a picture and
// a labelled sheet per call, what `facet preview` writes byte for byte, its
// settings refused under the rules and names of its flags.
#include <gtest/gtest.h>
#include <unistd.h>

#include <facet/facet.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "api_scenes.h"

namespace {

using namespace facet::testing;
namespace fs = std::filesystem;

std::string contentsOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Small and quick on the CPU, with no time limit, so that the rounds do not
// depend on how busy the machine is.
facet::PreviewSettings quickPreview() {
  facet::PreviewSettings s;
  s.materials = {"gold", "copper"};
  s.width = 24;
  s.height = 16;
  s.maxSpp = 8;
  s.backend = facet::Backend::Cpu;
  return s;
}

TEST(ApiPreview, EachMaterialsPictureAndTheLabelledSheet) {
  const facet::PreviewSheet sheet = renderer().preview(facet::loadScene(kCube), quickPreview());
  ASSERT_EQ(sheet.pictures.size(), 2u);
  EXPECT_EQ(sheet.pictures[0].label, "gold");
  EXPECT_EQ(sheet.pictures[1].label, "copper");
  for (const facet::PreviewPicture& p : sheet.pictures) {
    EXPECT_EQ(p.image.width, 24);
    EXPECT_EQ(p.image.height, 16);
    EXPECT_EQ(p.rgba.size(), 24u * 16u * 4u);
    EXPECT_GE(p.sampling.rounds, 2) << "adaptive rounds";
    EXPECT_LE(p.sampling.sppMax, 8);
  }
  EXPECT_NE(sheet.pictures[0].rgba, sheet.pictures[1].rgba);
  EXPECT_GT(sheet.width, 2 * 24);
  EXPECT_GT(sheet.height, 16) << "with the labels' strip";
  EXPECT_EQ(sheet.rgba.size(), std::size_t(sheet.width) * std::size_t(sheet.height) * 4u);
}

TEST(ApiPreview, TheSheetIsTheCommandLinesByteForByte) {
  const fs::path folder = fs::temp_directory_path() / ("facet_api_preview_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path cli = folder / "cli.png", api = folder / "api.png";
  const std::string command = std::string(FACET_BINARY) + " preview gold copper --model " + kCube +
                              " --size 24x16 --max-spp 8 --backend cpu --time-limit 86400 --quiet -o " + cli.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  renderer().writePreview(facet::loadScene(kCube), quickPreview(), api.string());
  EXPECT_EQ(contentsOf(api), contentsOf(cli));
  fs::remove_all(folder);
}

TEST(ApiPreview, BadSettingsAreRefusedByTheFlagsRules) {
  const facet::Scene cube = facet::loadScene(kCube);
  const auto refusal = [&](auto&& change) {
    facet::PreviewSettings s = quickPreview();
    change(s);
    return errorOf([&] { renderer().preview(cube, s); });
  };
  EXPECT_EQ(refusal([](facet::PreviewSettings& s) { s.materials.clear(); }),
            "preview settings: materials: give at least one material (a preset or a material file)");
  EXPECT_EQ(refusal([](facet::PreviewSettings& s) { s.noiseThreshold = 0; }),
            "preview settings: noiseThreshold: expected a number in (0, 1]");
  EXPECT_EQ(refusal([](facet::PreviewSettings& s) { s.maxSpp = 4; }).rfind("preview settings: maxSpp: ", 0), 0u);
  EXPECT_EQ(refusal([](facet::PreviewSettings& s) { s.turntable = 1; }),
            "preview settings: turntable: expected frames in [2, 3600]");
  EXPECT_EQ(refusal([](facet::PreviewSettings& s) {
              s.materials = {"unobtainium"};
            }).rfind("material 'unobtainium': preset: unknown preset", 0),
            0u);
  EXPECT_EQ(errorOf([&] { renderer().preview(cube, quickPreview(), 1); }),
            "preview settings: frame: expected one of the 1 frames, from 0");
  facet::PreviewSettings turning = quickPreview();
  turning.turntable = 4;
  try {
    renderer().writePreview(cube, turning, "turn.png");
    FAIL() << "a turntable written as a PNG";
  } catch (const facet::Error& e) {
    EXPECT_EQ(e.kind(), facet::ErrorKind::OutputFailed);
    EXPECT_EQ(std::string(e.what()), "output 'turn.png': a turntable is a movie: .mp4 or .gif");
  }
}

}  // namespace

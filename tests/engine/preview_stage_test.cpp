// The preview stage on the CPU reference: one picture per material, in the
// materials' order, labelled with the material's name and of the model's
// size, laid out on a sheet of the layout's size, each what its material
// alone shows; a turntable turns the
// model before a fixed camera and light, or the environment; a material that does not load is named; the sheet
// is written as a PNG.
#include "engine/preview_stage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/ground_blob.h"
#include "tests/support/temp_dir.h"

namespace facet {
namespace {

// Few samples: the test is about what the stage returns, not how clean it is.
PreviewStageSettings quickSettings() {
  PreviewStageSettings s;
  s.adaptive.maxSpp = 8;
  s.adaptive.minRounds = 2;
  s.adaptive.tileSize = 8;
  s.backend = Backend::Cpu;
  return s;
}

scene::Scene smallModel() {
  scene::Scene model = studioLitModel(testing::blobOverGround());
  model.render.width = 24;
  model.render.height = 16;
  return model;
}

TEST(PreviewStage, OnePictureAMaterialWithItsNameAndTheModelsSize) {
  Renderer renderer;
  int reported = 0;
  const PreviewStage stage(smallModel(), {"gold", "silver"}, quickSettings());
  ASSERT_EQ(stage.frames(), 1);
  const PreviewSheet sheet = stage.render(renderer, 0, [&](const PreviewPicture&) { ++reported; });
  EXPECT_EQ(reported, 2) << "the progress sees each picture";
  ASSERT_EQ(sheet.pictures.size(), 2u);
  EXPECT_EQ(sheet.pictures[0].label, stage.labels()[0]);
  EXPECT_EQ(sheet.pictures[1].label, stage.labels()[1]);
  EXPECT_NE(sheet.pictures[0].label, sheet.pictures[1].label);
  EXPECT_EQ(sheet.pictures[0].label.find('/'), std::string::npos);
  for (const PreviewPicture& p : sheet.pictures) {
    EXPECT_EQ(p.frame, 0);
    EXPECT_EQ(p.report.image.width, 24);
    EXPECT_EQ(p.report.image.height, 16);
    EXPECT_EQ(p.rgba.size(), 24u * 16u * 4u) << p.label;
    EXPECT_LE(p.report.tileSpp.front(), 8) << "the sample cap holds";
  }
  EXPECT_NE(sheet.pictures[0].rgba, sheet.pictures[1].rgba) << "each cell wears its own material";
  const ContactSheetLayout& layout = stage.layout();
  EXPECT_EQ(layout.count, 2);
  EXPECT_EQ(layout.cellWidth, 24);
  EXPECT_EQ(layout.cellHeight, 16);
  EXPECT_EQ(sheet.rgba.size(), std::size_t(layout.width()) * std::size_t(layout.height()) * 4u);
}

// The ground's renders of a cell without paths are the next such cell's
// too; a cell whose material runs paths (a glass) renders its own. Either way
// each cell is what its material alone would show.
TEST(PreviewStage, CellsShowWhatEachMaterialAloneShows) {
  Renderer renderer;
  const std::string glass = (std::filesystem::path(FACET_EXAMPLES_DIR) / "materials" / "glass.json").string();
  const std::vector<std::string> materials = {"gold", glass, "silver"};
  scene::Scene model = smallModel();
  model.render.bouncesStated = false;                      // facet chooses: paths for the glass only
  model.render.method = scene::IntersectionMethod::Exact;  // whose convexity it checks
  const PreviewSheet sheet = PreviewStage(model, materials, quickSettings()).render(renderer, 0);
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const PreviewSheet alone = PreviewStage(model, {materials[i]}, quickSettings()).render(renderer, 0);
    EXPECT_EQ(sheet.pictures[i].report.image.beauty, alone.pictures[0].report.image.beauty) << materials[i];
  }
  EXPECT_EQ(sheet.pictures[0].report.render.lightTransport.bounces, 0);
  EXPECT_GT(sheet.pictures[1].report.render.lightTransport.bounces, 0);
}

double meanOf(const std::vector<glm::vec4>& beauty) {
  double sum = 0;
  for (const glm::vec4& v : beauty) sum += double(v.r) + double(v.g) + double(v.b);
  return sum / double(beauty.size());
}

// The blob is the cube cage's limit surface, centred on the camera's target:
// a quarter turn brings it onto itself, an eighth does not.
TEST(PreviewStage, ATurntableTurnsTheModelBeforeAFixedCameraAndLight) {
  PreviewStageSettings settings = quickSettings();
  settings.turntable = 8;
  const PreviewStage stage(smallModel(), {"gold"}, settings);
  ASSERT_TRUE(stage.turntable());
  ASSERT_EQ(stage.frames(), 8);
  Renderer renderer;
  const PreviewSheet first = stage.render(renderer, 0), eighth = stage.render(renderer, 1),
                     quarter = stage.render(renderer, 2);
  EXPECT_EQ(eighth.frame, 1);
  EXPECT_EQ(eighth.pictures.at(0).frame, 1);
  const double still = meanOf(first.pictures.at(0).report.image.beauty);
  // Within 0.1%: the turned patches are diced and split into triangles in
  // another order; turning the light instead moves the mean by several percent.
  EXPECT_NEAR(meanOf(quarter.pictures.at(0).report.image.beauty), still, 1e-3 * still)
      << "a quarter turn of the cube under the same light is the same picture";
  EXPECT_NE(first.pictures.at(0).rgba, eighth.pictures.at(0).rgba) << "an eighth turn shows the cube otherwise";
  EXPECT_THROW(stage.render(renderer, 8), std::invalid_argument);
}

TEST(PreviewStage, ATurntableOfTheEnvironmentChangesTheLightOnTheModel) {
  PreviewStageSettings settings = quickSettings();
  settings.turntable = 4;
  settings.turn = scene::TurntableTurn::Environment;
  settings.ground = false;
  const PreviewStage stage(smallModel(), {"gold"}, settings);
  Renderer renderer;
  const double still = meanOf(stage.render(renderer, 0).pictures.at(0).report.image.beauty);
  const double quarter = meanOf(stage.render(renderer, 1).pictures.at(0).report.image.beauty);
  EXPECT_GT(std::abs(quarter - still), 0.02 * still) << "the studio's lamps swing round the cube";
}

TEST(PreviewStage, AMaterialThatDoesNotLoadIsNamed) {
  try {
    const PreviewStage stage(smallModel(), {"gold", "no-such-preset"}, quickSettings());
    FAIL() << "an unknown preset loaded";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("material 'no-such-preset': ", 0), 0u) << e.what();
  }
}

class PreviewStageFiles : public testing::TempDirTest {};

TEST_F(PreviewStageFiles, WritesTheSheetAsAPng) {
  PreviewStageSettings settings = quickSettings();
  settings.ground = false;
  const PreviewStage stage(smallModel(), {"gold"}, settings);
  Renderer renderer;
  const std::filesystem::path sheet = dir_ / "sheet.png";
  writePreviewStage(renderer, stage, sheet, 24, "");
  ASSERT_TRUE(std::filesystem::is_regular_file(sheet));
  EXPECT_GT(std::filesystem::file_size(sheet), 8u);
}

}  // namespace
}  // namespace facet

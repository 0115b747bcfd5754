#include "engine/preview_stage.h"

#include <stdexcept>
#include <utility>

#include "engine/image/image_io.h"
#include "engine/image/movie.h"
#include "engine/image/output_folder.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/studio_environment.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The model with `reference` on every object, and the material's name.
std::pair<scene::Scene, std::string> withMaterial(const scene::Scene& model, const std::string& reference) {
  scene::Scene scene = model;
  materials::Material material;
  try {
    material = scene::loadMaterialReference(reference, scene.textures);
  } catch (const scene::InputError& e) {
    // A preset's errors name render's flag; here the material is one of a list.
    const std::string message = e.what(), flag = "--material: ";
    if (message.rfind(flag, 0) != 0) throw;
    throw std::invalid_argument("material '" + reference + "': " + message.substr(flag.size()));
  }
  std::string label = material.name;
  scene::assignMaterial(scene, "", std::move(material));
  return {std::move(scene), std::move(label)};
}

}  // namespace

scene::Scene studioLitModel(scene::Scene model) {
  model.lights.clear();
  model.environment = scene::studioEnvironment();
  return model;
}

PreviewStage::PreviewStage(const scene::Scene& model, const std::vector<std::string>& materials,
                           const PreviewStageSettings& settings)
    : model_(model), settings_(settings) {
  for (const std::string& reference : materials) {
    auto [scene, label] = withMaterial(model, reference);
    scenes_.push_back(std::move(scene));
    labels_.push_back(std::move(label));
  }
  layout_ = contactSheetLayout(int(scenes_.size()), model.render.width, model.render.height, settings.columns);
  if (settings.ground) ground_ = scene::groundScenes(model);
}

scene::Scene PreviewStage::turned(const scene::Scene& scene, int frame) const {
  return settings_.turntable ? scene::turntableFrame(scene, frame, *settings_.turntable, settings_.turn) : scene;
}

PreviewSheet PreviewStage::render(Renderer& renderer, int frame, const PreviewProgress& progress) const {
  if (frame < 0 || frame >= frames())
    throw std::invalid_argument("preview frame " + std::to_string(frame) + ": expected one of the " +
                                std::to_string(frames()) + " frames");
  const int width = model_.render.width, height = model_.render.height;
  // The ground turns with what turns: it stays under the model, and is lit as the model is.
  std::optional<scene::GroundScenes> ground = ground_;
  if (ground) ground->holdout = turned(ground->holdout, frame), ground->ground = turned(ground->ground, frame);
  PreviewSheet sheet;
  sheet.frame = frame;
  std::vector<ContactCell> cells;
  SharedGroundRenders sharedGround;
  for (std::size_t i = 0; i < scenes_.size(); ++i) {
    const scene::Scene scene = turned(scenes_[i], frame);
    PreviewPicture picture{
        labels_[i],
        frame,
        renderAdaptive(renderer, scene, settings_.backend, settings_.adaptive, {std::nullopt, settings_.threads}, {},
                       ground ? &*ground : nullptr, &sharedGround),
        {}};
    picture.rgba = previewPixels(picture.report.image.beauty, width, height, settings_.look);
    cells.push_back({picture.rgba, picture.label});
    if (progress) progress(picture);
    sheet.pictures.push_back(std::move(picture));
  }
  sheet.rgba = composeContactSheet(layout_, cells);
  return sheet;
}

void writePreviewStage(Renderer& renderer, const PreviewStage& stage, const fs::path& output, double fps,
                       const std::string& searchPath, const PreviewProgress& progress) {
  const ContactSheetLayout& layout = stage.layout();
  if (!stage.turntable()) {
    const PreviewSheet sheet = stage.render(renderer, 0, progress);
    writeAllOrNothing({rgbaPngFile(output, layout.width(), layout.height(), sheet.rgba)});
    return;
  }
  // The frames go when the movie is made or abandoned, whichever way that ends.
  const ScratchFolder folder("--movie", "the turntable's frames", "preview");
  const bool pictureAlone = layout.count == 1;
  for (int frame = 0; frame < stage.frames(); ++frame) {
    const fs::path file = framePath(folder.path(), frame);
    const PreviewSheet sheet = stage.render(renderer, frame, progress);
    if (pictureAlone)
      rgbaPngFile(file, layout.cellWidth, layout.cellHeight, sheet.pictures.front().rgba).write(file);
    else
      rgbaPngFile(file, layout.width(), layout.height(), sheet.rgba).write(file);
  }
  writeMovie(folder.path(), stage.frames(), fps, output, searchPath);
}

}  // namespace facet

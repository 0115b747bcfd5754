// The preview stage (docs/preview-stage.md): materials on a model under one
// environment, each rendered by adaptive sampling over a shadow-catching
// ground and laid out as a labelled contact sheet, one sheet per frame of an
// optional turntable that turns the model (or the environment) before a
// fixed camera, written as a PNG or handed to ffmpeg as a movie. The
// command line (`facet preview`) and the APIs call it alike.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/adaptive_render.h"
#include "engine/image/contact_sheet.h"
#include "engine/image/preview.h"
#include "engine/renderer.h"
#include "scenes/ground_plane.h"
#include "scenes/placement.h"
#include "scenes/scene.h"

namespace facet {

struct PreviewStageSettings {
  AdaptiveSettings adaptive;
  PreviewOptions look;             // how each cell's beauty becomes 8-bit pixels
  int columns = 0;                 // of the sheet; 0: a grid about as wide as tall
  std::optional<int> turntable;    // frames of a full turn (scenes/placement.h)
  scene::TurntableTurn turn = scene::TurntableTurn::Model;  // what the turntable turns
  bool ground = true;              // a ground that catches the model's shadow and is otherwise unseen
  Backend backend = Backend::Gpu;
  unsigned threads = 0;            // the CPU reference's; 0: every core
};

// The model as the stage lights it: its lights gone, under the studio
// environment (scenes/studio_environment.h), which a caller may replace.
scene::Scene studioLitModel(scene::Scene model);

// One material's picture in one frame.
struct PreviewPicture {
  std::string label;  // the material's name: a file's without its folder and .json, or the preset's
  int frame = 0;
  AdaptiveReport report;           // the render: its float image, rounds, samples and noise
  std::vector<std::uint8_t> rgba;  // the cell: the beauty through settings.look, row 0 at the top
};

struct PreviewSheet {
  int frame = 0;
  std::vector<PreviewPicture> pictures;  // one per material, in the materials' order
  std::vector<std::uint8_t> rgba;        // the contact sheet, layout().width() x layout().height()
};

// Called after each picture is rendered, before the next starts.
using PreviewProgress = std::function<void(const PreviewPicture& picture)>;

class PreviewStage {
 public:
  // `model` at its render size, lit as it will be (studioLitModel), and the
  // materials as files (.json) or presets, each put on every object of the
  // model. Throws std::invalid_argument "material '<reference>': <rule>" or
  // scene::InputError naming the file for a material that does not load,
  // and std::invalid_argument for settings that break their rules.
  PreviewStage(const scene::Scene& model, const std::vector<std::string>& materials,
               const PreviewStageSettings& settings);

  bool turntable() const { return settings_.turntable.has_value(); }
  int frames() const { return settings_.turntable.value_or(1); }
  const ContactSheetLayout& layout() const { return layout_; }
  const std::vector<std::string>& labels() const { return labels_; }

  // Frame `frame` (0 without a turntable): every material's picture and the sheet.
  PreviewSheet render(Renderer& renderer, int frame, const PreviewProgress& progress = {}) const;

 private:
  scene::Scene model_;
  std::vector<scene::Scene> scenes_;  // the model with each material
  std::vector<std::string> labels_;
  PreviewStageSettings settings_;
  ContactSheetLayout layout_;
  std::optional<scene::GroundScenes> ground_;  // the same under every material

  // `scene` as frame `frame` shows it.
  scene::Scene turned(const scene::Scene& scene, int frame) const;
};

// Every frame of `stage`, written as the sheet `output` (a .png) without a
// turntable, or with one as the movie `output` (.mp4 or .gif) at `fps`,
// whose frames are the picture alone for one material and the sheet for
// several (labels belong to sheets), made
// by the ffmpeg found on `searchPath` (PATH's syntax) from frames in a
// temporary folder that goes whichever way this ends. Throws OutputError
// (engine/image/image_io.h) where a file cannot be written or ffmpeg fails.
void writePreviewStage(Renderer& renderer, const PreviewStage& stage, const std::filesystem::path& output,
                       double fps, const std::string& searchPath, const PreviewProgress& progress = {});

}  // namespace facet

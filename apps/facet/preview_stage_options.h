// The flags of `facet preview` (docs/preview-stage.md): the model, its
// lighting, the cells' size and the sheet's columns, adaptive sampling's
// threshold and caps, and the turntable movie.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "engine/adaptive_render.h"
#include "preview_options.h"
#include "scene_options.h"

namespace facet::cli {

struct PreviewStageFlags {
  std::vector<std::string> materials;  // files or presets, one cell each
  std::string model;                   // empty: the default scene's superball
  std::string output;                  // -o: the sheet, a .png
  std::string size = "256x256";        // of each cell
  int columns = 0;
  SceneOverrides lighting;  // --env, --env-intensity, --env-rotation and --ibl
  double noiseThreshold = AdaptiveSettings{}.noiseThreshold;
  long long maxSpp = AdaptiveSettings{}.maxSpp;
  double timeLimit = 60;  // seconds per image: a preview answers while one waits, where the API renders to the end
  std::optional<int> turntable;  // frames of a full turn
  std::string turn = "model";    // what it turns
  std::string movie;             // .mp4 or .gif
  double fps = 24;
  bool noGround = false;  // no shadow-catching ground under the model
  PreviewFlags preview;
  std::string backend = "gpu";
  std::string adapter;
  bool quiet = false;
  bool json = false;
};

void addPreviewStageOptions(CLI::App& command, PreviewStageFlags& flags);

// Throws std::invalid_argument "<flag> '<value>': <rule>" for the first
// flag that breaks its rule, or for a sheet without an output.
AdaptiveSettings chosenAdaptiveSettings(const PreviewStageFlags& flags);
void checkPreviewStageFlags(const PreviewStageFlags& flags);

}  // namespace facet::cli

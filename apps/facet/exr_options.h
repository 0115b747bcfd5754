// facet render's EXR flags (--aovs, --half) and what the EXR says about
// the render: its placement, camera, settings and the scene's names.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "engine/image/exr_file.h"
#include "scenes/scene.h"

namespace facet::cli {

struct ExrCommandOptions {
  std::string aovs = "all";
  bool half = false;
};

void addExrOptions(CLI::App& command, ExrCommandOptions& options);

// Throws std::invalid_argument for a bad --aovs, before any render.
ExrLayers chosenExrLayers(const ExrCommandOptions& options);

// The EXR options of a render of `scene` (its camera the frame's) whose
// pixels are `window` of the full image.
ExrOptions exrOptions(const scene::Scene& scene, const std::string& backend, const PixelRect& window,
                      const ExrCommandOptions& options);

}  // namespace facet::cli

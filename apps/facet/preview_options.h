// The flags of a PNG preview, shared by `facet render` and `facet merge`:
// --exposure, --tonemap, --background and --alpha (docs/preview.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "engine/image/preview.h"

namespace facet::cli {

struct PreviewFlags {
  float exposure = 0;
  std::string tonemap = "pbr-neutral";
  std::vector<double> background;  // R,G,B; empty: the environment as rendered
  bool alpha = false;
};

void addPreviewOptions(CLI::App& command, PreviewFlags& flags);

// Throws std::invalid_argument "<flag> '<value>': <rule>" for a curve
// kToneCurveNames does not list or a negative background.
PreviewOptions chosenPreview(const PreviewFlags& flags);

}  // namespace facet::cli

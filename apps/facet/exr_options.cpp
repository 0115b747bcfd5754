#include "exr_options.h"

#include "engine/render_record.h"

namespace facet::cli {

void addExrOptions(CLI::App& command, ExrCommandOptions& options) {
  command.add_option(
      "--aovs", options.aovs,
      "EXR layers: all, beauty, or a comma-separated list of: " + exrLayerNames() + " (the beauty is always written)");
  command.add_flag("--half", options.half, "Write the EXR's beauty as 16-bit half floats");
}

ExrLayers chosenExrLayers(const ExrCommandOptions& options) { return parseExrLayers(options.aovs, "--aovs"); }

ExrOptions exrOptions(const scene::Scene& scene, const std::string& backend, const PixelRect& window,
                      const ExrCommandOptions& options) {
  return describedExr(scene, backend, window, chosenExrLayers(options), options.half);
}

}  // namespace facet::cli

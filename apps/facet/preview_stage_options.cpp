#include "preview_stage_options.h"

#include <stdexcept>

#include "engine/image/movie.h"
#include "farm_options.h"
#include "sampling_options.h"

namespace facet::cli {

void addPreviewStageOptions(CLI::App& c, PreviewStageFlags& f) {
  c.add_option("materials", f.materials, "Material files (.json), presets (see `facet presets`) or names of the shipped "
                 "library (scenes/examples/materials: glass, glazed_ceramic, ...), one cell each")
      ->required();
  c.add_option("--model", f.model, "The model every material is put on (default: the default scene's superball)")
      ->check(CLI::ExistingFile);
  c.add_option("-o,--output", f.output, "The contact sheet, a .png");
  c.add_option("--size", f.size, "Each cell's image size WIDTHxHEIGHT (default 256x256)");
  c.add_option("--columns", f.columns, "Cells per row (default: a grid about as wide as tall)")
      ->check(CLI::Range(1, 64));
  addEnvironmentOptions(c, f.lighting);
  c.add_option("--ibl", f.lighting.ibl, "How the environment lights the model (default: prefiltered, or sampled with "
                 "occlusion where paths run)")
      ->check(CLI::IsMember({"sampled", "prefiltered", "filtered"}));
  c.add_flag("--no-ground", f.noGround,
             "No ground under the model (default: a ground that catches the model's shadow and is otherwise unseen)");
  c.add_option("--noise-threshold", f.noiseThreshold,
               "Stop a tile once its relative standard error is below this (default 0.02)");
  c.add_option("--max-spp", f.maxSpp, "At most this many camera samples per pixel (default 256)");
  c.add_option("--time-limit", f.timeLimit, "Seconds per image after which no round starts (default 60)");
  c.add_option("--turntable", f.turntable,
               "Frames of a full turn of the model (see --turn) about the vertical through the camera's target, "
               "for --movie")
      ->check(CLI::Range(2, 3600));
  addTurnOption(c, f.turn)->needs(c.get_option("--turntable"));
  c.add_option("--movie", f.movie, "The turntable as an .mp4 or a .gif, made by ffmpeg (found on PATH)");
  c.add_option("--fps", f.fps, "The movie's frames per second (default 24)")->check(CLI::Range(1.0, 120.0));
  addPreviewOptions(c, f.preview);
  c.add_option("--backend", f.backend, "Renderer backend: the GPU kernels or the CPU reference")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  c.add_option("--adapter", f.adapter, "GPU adapter: a substring of its name (default: FACET_ADAPTER or the first)");
  c.add_flag("--quiet", f.quiet, "No summary lines");
  c.add_flag("--json", f.json, "The summary as JSON on stdout");
}

AdaptiveSettings chosenAdaptiveSettings(const PreviewStageFlags& f) {
  AdaptiveSettings settings;
  settings.noiseThreshold = checkedNoiseThreshold(f.noiseThreshold);
  settings.maxSpp = checkedMaxSpp(f.maxSpp);
  settings.timeLimitSeconds = checkedTimeLimit(f.timeLimit);
  return settings;
}

void checkPreviewStageFlags(const PreviewStageFlags& f) {
  if (f.movie.empty() && f.turntable) throw std::invalid_argument("--turntable: give --movie out.mp4 or out.gif");
  if (!f.movie.empty()) {
    if (!f.turntable) throw std::invalid_argument("--movie '" + f.movie + "': give --turntable N, its frames");
    if (!movieFormat(f.movie))
      throw std::invalid_argument("--movie '" + f.movie + "': the extension chooses the format: expected .mp4 or .gif");
    if (!f.output.empty())
      throw std::invalid_argument("-o '" + f.output + "': --movie writes the movie alone; give one or the other");
  } else if (f.output.empty()) {
    throw std::invalid_argument("give -o sheet.png, or --turntable N --movie out.mp4|out.gif");
  }
}

}  // namespace facet::cli

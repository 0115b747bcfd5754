// facet preview: materials on a model under one environment, each
// rendered by adaptive sampling and laid out as a labelled contact sheet, or
// turned about the model as a movie (docs/preview-stage.md).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "commands.h"
#include "data_folder.h"
#include "engine/image/image_io.h"
#include "engine/image/child_process.h"
#include "engine/image/movie.h"
#include "engine/image_memory.h"
#include "engine/preview_stage.h"
#include "farm_options.h"
#include "material_options.h"
#include "preview_stage_options.h"
#include "render_summary.h"
#include "scene_options.h"
#include "scenes/input_file.h"

namespace facet::cli {
namespace {

// The model as loaded, lit by the studio environment or --env alone, at the
// cell size.
scene::Scene previewModel(const PreviewStageFlags& f) {
  const std::string model =
      f.model.empty() ? (dataFolder() / "scenes" / "examples" / "superball.obj").string() : f.model;
  scene::Scene scene = studioLitModel(loadEditedScene(model, {}));
  applyImageSize(f.size, scene);
  applySceneOverrides(f.lighting, scene);
  checkImagesFitInMemory(scene, int(f.materials.size()) + 1, "--size");
  return scene;
}

nlohmann::json renderJson(const std::string& label, int frame, const AdaptiveReport& r) {
  nlohmann::json render = adaptiveJson(r);
  render["material"] = label;
  render["frame"] = frame;
  render["tile_errors"] = r.errors;
  render["milliseconds"] = r.seconds * 1000.0;
  render["stages_ms"] = stagesJson(r.render);
  render["bounces"] = r.render.lightTransport.bounces;
  render["light_transport"] = r.render.lightTransport.note;
  return render;
}

void printRender(const nlohmann::json& r, bool turntable) {
  const std::string frame = turntable ? " frame " + std::to_string(int(r["frame"])) : std::string();
  const std::string transport = r["light_transport"];
  std::printf("%s%s: %d rounds, %d-%d spp (mean %.1f), largest tile error %.4f (threshold %g): %s, %.2f s%s\n",
              std::string(r["material"]).c_str(), frame.c_str(), int(r["rounds"]), int(r["spp_min"]), int(r["spp_max"]),
              double(r["spp_mean"]), double(r["max_tile_error"]), double(r["noise_threshold"]),
              std::string(r["stop"]).c_str(), double(r["milliseconds"]) / 1000.0,
              transport.empty() ? "" : ("; " + transport).c_str());
}

void runPreview(const PreviewStageFlags& f) {
  checkPreviewStageFlags(f);
  PreviewStageSettings settings;
  settings.adaptive = chosenAdaptiveSettings(f);
  settings.look = chosenPreview(f.preview);
  settings.columns = f.columns;
  settings.turntable = f.turntable;
  settings.turn = chosenTurn(f.turn);
  settings.ground = !f.noGround;
  settings.backend = f.backend == "cpu" ? Backend::Cpu : Backend::Gpu;
  const char* searchPath = std::getenv("PATH");
  const std::string path = searchPath ? searchPath : "";
  // Every output is checked, and ffmpeg found, before the first render.
  if (!f.movie.empty()) {
    checkOutputPath("--movie", f.movie);
    if (!findOnPath("ffmpeg", path)) throw OutputError("--movie '" + f.movie + "': " + kFfmpegMissing);
  } else {
    checkOutputPath("-o", f.output);
    checkOutputExtension("-o", f.output, ".png");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string written = f.movie.empty() ? f.output : f.movie;
  const scene::InputFileLog inputs;  // the model's files, the lighting's and the materials'
  const scene::Scene model = previewModel(f);
  std::vector<std::string> materials;
  for (const std::string& reference : f.materials) materials.push_back(libraryMaterialReference(reference));
  const PreviewStage stage(model, materials, settings);
  checkNotAnInput(f.movie.empty() ? "-o" : "--movie", written, inputs.files());
  const ContactSheetLayout& layout = stage.layout();
  const int width = model.render.width, height = model.render.height, frames = stage.frames();
  Renderer renderer(f.adapter);
  nlohmann::json summary = {{"backend", f.backend},      {"width", layout.width()},
                            {"height", layout.height()}, {"cell_width", width},
                            {"cell_height", height},     {"frames", frames},
                            {"ground", settings.ground}, {"renders", nlohmann::json::array()}};
  const auto progress = [&](const PreviewPicture& picture) {
    summary["adapter"] = picture.report.render.device;
    summary["renders"].push_back(renderJson(picture.label, picture.frame, picture.report));
    if (!f.quiet && !f.json) printRender(summary["renders"].back(), stage.turntable());
  };
  writePreviewStage(renderer, stage, written, f.fps, path, progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["milliseconds"] = seconds * 1000.0;
  summary["output"] = written;
  if (f.json)
    std::printf("%s\n", summary.dump(2).c_str());
  else if (!f.quiet)
    std::printf("wrote %s: %d x %d cells of %dx%d, %d frame%s, %.2f s\n", written.c_str(), layout.columns, layout.rows,
                width, height, frames, frames == 1 ? "" : "s", seconds);
}

}  // namespace

void addPreviewCommand(CLI::App& app) {
  auto flags = std::make_shared<PreviewStageFlags>();
  auto* c = app.add_subcommand("preview",
                               "Materials on a model under the studio environment or a map: a contact sheet or a "
                               "turntable movie, anti-aliased by adaptive sampling");
  addPreviewStageOptions(*c, *flags);
  c->callback([flags] { runPreview(*flags); });
}

}  // namespace facet::cli

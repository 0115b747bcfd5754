// facet preview: materials on a model under one environment, each
// rendered by adaptive sampling and laid out as a labelled contact sheet, or
// turned about the model as a movie (docs/preview-stage.md).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "commands.h"
#include "data_folder.h"
#include "engine/adaptive_render.h"
#include "engine/camera/camera_path.h"
#include "engine/image/contact_sheet.h"
#include "engine/image/image_io.h"
#include "engine/image/movie.h"
#include "engine/image_memory.h"
#include "material_options.h"
#include "preview_stage_options.h"
#include "scene_options.h"
#include "scenes/ground_plane.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/studio_environment.h"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

// The turntable's frames, in a folder of their own that goes when the
// command ends, whichever way it ends.
class FrameFolder {
 public:
  FrameFolder() {
    std::random_device entropy;
    path_ =
        fs::temp_directory_path() / ("facet-preview-" + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
    fs::create_directory(path_);
  }
  ~FrameFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  FrameFolder(const FrameFolder&) = delete;
  FrameFolder& operator=(const FrameFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// The model as loaded, lit by the studio environment or --env alone, at the
// cell size.
scene::Scene previewModel(const PreviewStageFlags& f) {
  const std::string model =
      f.model.empty() ? (dataFolder() / "scenes" / "examples" / "superball.obj").string() : f.model;
  scene::Scene scene = loadEditedScene(model, {});
  scene.lights.clear();
  scene.environment = scene::studioEnvironment();
  applyImageSize(f.size, scene);
  applySceneOverrides(f.lighting, scene);
  checkImagesFitInMemory(scene, int(f.materials.size()) + 1, "--size");
  return scene;
}

// The model with `reference` on every object; the material's name (a file's
// without its folder and .json, or the preset's) labels its cell.
std::pair<scene::Scene, std::string> withMaterial(const scene::Scene& model, const std::string& reference) {
  scene::Scene scene = model;
  materials::Material material;
  try {
    material = scene::loadMaterialReference(reference, scene.textures);
  } catch (const scene::InputError& e) {
    // A preset's errors name render's flag; here the material is positional.
    const std::string message = e.what(), flag = "--material: ";
    if (message.rfind(flag, 0) != 0) throw;
    throw std::invalid_argument("material '" + reference + "': " + message.substr(flag.size()));
  }
  std::string label = material.name;
  scene::assignMaterial(scene, "", std::move(material));
  return {std::move(scene), std::move(label)};
}

nlohmann::json renderJson(const std::string& label, int frame, const AdaptiveReport& r, double threshold) {
  const auto [least, most] = std::minmax_element(r.tileSpp.begin(), r.tileSpp.end());
  return {{"material", label},        {"frame", frame},
          {"rounds", r.rounds},       {"samples", r.samples},
          {"spp_mean", r.sppMean},    {"spp_min", *least},
          {"spp_max", *most},         {"max_tile_error", r.maxError},
          {"tile_errors", r.errors},  {"noise_threshold", threshold},
          {"stop", toString(r.stop)}, {"milliseconds", r.seconds * 1000.0}};
}

void printRender(const nlohmann::json& r, bool turntable) {
  const std::string frame = turntable ? " frame " + std::to_string(int(r["frame"])) : std::string();
  std::printf("%s%s: %d rounds, %d-%d spp (mean %.1f), largest tile error %.4f (threshold %g): %s, %.2f s\n",
              std::string(r["material"]).c_str(), frame.c_str(), int(r["rounds"]), int(r["spp_min"]), int(r["spp_max"]),
              double(r["spp_mean"]), double(r["max_tile_error"]), double(r["noise_threshold"]),
              std::string(r["stop"]).c_str(), double(r["milliseconds"]) / 1000.0);
}

void runPreview(const PreviewStageFlags& f) {
  checkPreviewStageFlags(f);
  const AdaptiveSettings settings = chosenAdaptiveSettings(f);
  const PreviewOptions look = chosenPreview(f.preview);
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
  const scene::Scene model = previewModel(f);
  std::vector<scene::Scene> scenes;
  std::vector<std::string> labels;
  for (const std::string& reference : f.materials) {
    auto [scene, label] = withMaterial(model, reference);
    scenes.push_back(std::move(scene));
    labels.push_back(std::move(label));
  }
  const int width = model.render.width, height = model.render.height;
  const ContactSheetLayout layout = contactSheetLayout(int(scenes.size()), width, height, f.columns);
  const Backend backend = f.backend == "cpu" ? Backend::Cpu : Backend::Gpu;
  const int frames = f.turntable.value_or(1);
  std::unique_ptr<FrameFolder> folder = f.movie.empty() ? nullptr : std::make_unique<FrameFolder>();
  // The ground's scenes are the same under every material.
  const std::optional<scene::GroundScenes> ground =
      f.noGround ? std::nullopt : std::optional(scene::groundScenes(model));
  Renderer renderer(f.adapter);
  nlohmann::json summary = {{"backend", f.backend},      {"width", layout.width()},
                            {"height", layout.height()}, {"cell_width", width},
                            {"cell_height", height},     {"frames", frames},
                            {"ground", bool(ground)},    {"renders", nlohmann::json::array()}};
  for (int frame = 0; frame < frames; ++frame) {
    const scene::Camera camera =
        f.turntable ? camera::turntableCamera(model.camera, frame, *f.turntable) : model.camera;
    std::optional<scene::GroundScenes> framed = ground;
    if (framed) framed->holdout.camera = framed->ground.camera = camera;
    std::vector<ContactCell> cells;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      scene::Scene scene = scenes[i];
      scene.camera = camera;
      const AdaptiveReport report = renderAdaptive(renderer, scene, backend, settings, 0, framed ? &*framed : nullptr);
      cells.push_back({previewPixels(report.image.beauty, width, height, look), labels[i]});
      summary["adapter"] = report.first.device;
      summary["renders"].push_back(renderJson(labels[i], frame, report, settings.noiseThreshold));
      if (!f.quiet && !f.json) printRender(summary["renders"].back(), bool(f.turntable));
    }
    const std::vector<std::uint8_t> sheet = composeContactSheet(layout, cells);
    if (folder)
      rgbaPngFile(framePath(folder->path(), frame), layout.width(), layout.height(), sheet)
          .write(framePath(folder->path(), frame));
    else
      writeAllOrNothing({rgbaPngFile(f.output, layout.width(), layout.height(), sheet)});
  }
  if (folder) writeMovie(folder->path(), frames, f.fps, f.movie, path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["milliseconds"] = seconds * 1000.0;
  const std::string written = f.movie.empty() ? f.output : f.movie;
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

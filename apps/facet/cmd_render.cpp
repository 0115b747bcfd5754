// facet render: a scene file (or a bare cage) to EXR with every AOV, and a
// PNG preview; or a crop, a tile or a range of frames of it (farm_options.h).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "commands.h"
#include "engine/image/image_io.h"
#include "engine/renderer.h"
#include "exr_options.h"
#include "farm_options.h"
#include "progress_log.h"
#include "render_summary.h"
#include "scene_options.h"
#include "scenes/scene_file.h"

namespace facet::cli {
namespace {

struct RenderCommandOptions {
  std::string scene;
  std::string exr;
  std::string png;
  float exposure = 0;
  SceneOverrides scene_overrides;
  FarmOptions farm;
  std::string backend = "gpu";
  std::string adapter;
  ExrCommandOptions exrFlags;
};

// A single frame may keep a name without '#'; a range needs it.
std::vector<RenderJob> renderJobs(const RenderCommandOptions& o) {
  const std::vector<int> frames = chosenFrames(o.farm);
  if (frames.empty()) return {{std::nullopt, o.exr, o.png}};
  auto name = [&](const char* flag, const std::string& pattern, int frame) {
    const bool numbered = frames.size() > 1 || pattern.find('#') != std::string::npos;
    return pattern.empty() || !numbered ? pattern : framePath(flag, pattern, frame);
  };
  std::vector<RenderJob> jobs;
  for (int frame : frames) jobs.push_back({frame, name("-o", o.exr, frame), name("--png", o.png, frame)});
  return jobs;
}

// Every output of every frame is checked before the first render, and each
// frame's are written as a set, so a failure leaves no new file of that
// frame and every old one as it was.
void checkOutputs(const RenderJob& job) {
  checkOutputPath("-o", job.exr);
  if (job.png.empty()) return;
  checkOutputPath("--png", job.png);
  if (std::filesystem::absolute(job.png).lexically_normal() == std::filesystem::absolute(job.exr).lexically_normal())
    throw OutputError("--png '" + job.png + "': names the same file as -o");
}

void runRender(const RenderCommandOptions& o) {
  const std::vector<RenderJob> jobs = renderJobs(o);
  for (const RenderJob& job : jobs) checkOutputs(job);
  chosenExrLayers(o.exrFlags);
  scene::Scene scene = scene::loadScene(o.scene);
  applySceneOverrides(o.scene_overrides, scene);
  const int width = scene.render.width, height = scene.render.height;
  const std::optional<PixelRect> crop = chosenCrop(o.farm, width, height);
  checkImagesFitInMemory(scene, 1, o.scene_overrides.size.empty() ? o.scene + ": image size" : "--size", crop);
  if (scene.environment && scene.environment->map->clampedTexels > 0)
    std::fprintf(stderr, "warning: %s: %zu texels were negative, NaN or Inf and are set to 0\n",
                 scene.environment->map->source.c_str(), scene.environment->map->clampedTexels);
  const Backend backend = o.backend == "cpu" ? Backend::Cpu : Backend::Gpu;
  const unsigned threads = chosenThreads(o.farm);
  if (backend == Backend::Gpu) limitLavapipeThreads(threads);

  Renderer renderer(o.adapter);
  const scene::Camera still = scene.camera;
  nlohmann::json summary = {{"backend", o.backend},
                            {"width", width},
                            {"height", height},
                            {"spp", scene.render.samplesPerPixel},
                            {"renders", nlohmann::json::array()}};
  for (const RenderJob& job : jobs) {
    scene.camera = job.frame ? frameCamera(still, scene.cameraKeys, o.farm, *job.frame) : still;
    const auto start = std::chrono::steady_clock::now();
    ProgressLog progress(job.frame ? "frame " + std::to_string(*job.frame) : std::string("rendering"),
                         o.farm.quiet || o.farm.json);
    const RenderReport report = renderer.render(scene, backend, std::ref(progress), {crop, threads});
    progress.finish();
    const double wallMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    std::vector<OutputFile> outputs{
        exrFile(job.exr, report.image, exrOptions(scene, o.backend, report.window, o.exrFlags))};
    if (!job.png.empty()) outputs.push_back(pngFile(job.png, report.image, o.exposure));
    writeAllOrNothing(outputs);

    summary["adapter"] = report.device;
    summary["renders"].push_back(renderJson(report, job, wallMilliseconds));
    if (!o.farm.quiet && !o.farm.json) printSummary(scene, report, job, wallMilliseconds);
  }
  summary["peak_resident_bytes"] = peakResidentBytes();
  if (o.farm.json) std::printf("%s\n", summary.dump(2).c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderCommandOptions>();
  auto* c = app.add_subcommand("render", "Render a scene (.json), a control cage (.obj) or a glTF file");
  c->add_option("scene", o->scene, "Scene file")->required()->check(CLI::ExistingFile);
  c->add_option("-o,--output", o->exr, "EXR with the beauty and the --aovs layers ('#' for the frame number)")
      ->required();
  c->add_option("--png", o->png, "Also write an 8-bit sRGB preview");
  c->add_option("--exposure", o->exposure, "PNG exposure in stops");
  addSceneOverrideOptions(*c, o->scene_overrides);
  addFarmOptions(*c, o->farm);
  addExrOptions(*c, o->exrFlags);
  c->add_option("--backend", o->backend, "Renderer backend: the GPU kernels or the CPU reference")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  c->add_option("--adapter", o->adapter, "GPU adapter: a substring of its name (default: FACET_ADAPTER or the first)");
  c->callback([o] { runRender(*o); });
}

}  // namespace facet::cli

// facet render: a scene file (or a bare cage) to an EXR with every AOV, a
// PNG preview, or both; or a crop, a tile or a range of frames of it
// (farm_options.h); or, with --watch, a picture again on each change to its
// files (watch.h).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "commands.h"
#include "engine/adaptive_render.h"
#include "engine/image/image_io.h"
#include "engine/image_memory.h"
#include "engine/renderer.h"
#include "exr_options.h"
#include "farm_options.h"
#include "material_options.h"
#include "preview_options.h"
#include "progress_log.h"
#include "render_summary.h"
#include "sampling_options.h"
#include "scene_options.h"
#include "scene_warnings.h"
#include "scenes/input_file.h"
#include "scenes/sampling_choice.h"
#include "scenes/scene_file.h"
#include "watch.h"

namespace facet::cli {
namespace {

// Adaptive sampling's flags (docs/rendering.md, "Converged by default").
struct SamplingFlags {
  std::optional<double> noiseThreshold;
  std::optional<long long> maxSpp;
  std::optional<double> timeLimit;
};

struct RenderCommandOptions {
  std::string scene;
  std::string output;  // -o: an EXR or a PNG, by its extension
  bool writeExr = false;
  std::string exr;
  std::string png;
  std::string pngFlag = "--png";  // the flag that named the PNG
  PreviewFlags preview;
  SceneOverrides scene_overrides;
  SceneEdits edits;
  SamplingFlags sampling;
  FarmOptions farm;
  std::string backend = "gpu";
  std::string adapter;
  ExrCommandOptions exrFlags;
  WatchOptions watch;
  bool verbose = false;
};

std::string lowerCaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// -o's extension chooses its format.
void chooseOutputFormat(RenderCommandOptions& o) {
  const std::string extension = lowerCaseExtension(o.output);
  if (extension == ".png") {
    if (!o.png.empty())
      throw std::invalid_argument("--png '" + o.png + "': -o '" + o.output +
                                  "' is a PNG already; give -o an .exr to write both");
    o.png = o.output;
    o.pngFlag = "-o";
  } else if (extension == ".exr" || o.output.empty() || std::filesystem::is_directory(o.output)) {
    // An empty path or a folder is checkOutputPath's to reject.
    o.writeExr = true;
    o.exr = o.output;
  } else {
    throw std::invalid_argument("-o '" + o.output + "': the extension chooses the format: expected .exr or .png");
  }
}

// --png adds a preview to -o's EXR or stands alone. A tile is an EXR for
// facet merge, which writes the preview.
void chooseOutputs(RenderCommandOptions& o, bool outputGiven) {
  if (outputGiven)
    chooseOutputFormat(o);
  else if (o.png.empty())
    throw std::invalid_argument("give -o (an .exr or .png file), --png, or both");
  if (!o.farm.tile.empty() && !o.png.empty())
    throw std::invalid_argument(o.pngFlag + " '" + o.png +
                                "': a --tile render writes an EXR only; facet merge --png writes the preview");
}

// A job per number (a frame's or a seed's, `what`), '#' in the outputs
// standing for it; a single number may keep a name without '#', a range
// needs it.
template <class Number, class Job>
std::vector<RenderJob> numberedJobs(const RenderCommandOptions& o, const std::vector<Number>& numbers,
                                    const std::string& what, Job job) {
  auto name = [&](const char* flag, const std::string& pattern, Number number) {
    const bool numbered = numbers.size() > 1 || pattern.find('#') != std::string::npos;
    return pattern.empty() || !numbered ? pattern : framePath(flag, pattern, int(number), what);
  };
  std::vector<RenderJob> jobs;
  for (Number number : numbers)
    jobs.push_back(job(number, name("-o", o.exr, number), name(o.pngFlag.c_str(), o.png, number)));
  return jobs;
}

std::vector<RenderJob> renderJobs(const RenderCommandOptions& o) {
  if (const std::vector<std::uint32_t> seeds = chosenSeeds(o.farm); !seeds.empty()) {
    if (o.scene_overrides.seed) throw std::invalid_argument("--seed, --seeds: give one of them");
    return numberedJobs(o, seeds, "seed", [](std::uint32_t seed, std::string exr, std::string png) {
      return RenderJob{std::nullopt, std::move(exr), std::move(png), seed};
    });
  }
  const std::vector<int> frames = chosenFrames(o.farm);
  if (frames.empty()) return {{std::nullopt, o.exr, o.png}};
  return numberedJobs(o, frames, "frame", [](int frame, std::string exr, std::string png) {
    return RenderJob{frame, std::move(exr), std::move(png)};
  });
}

// Every output of every frame is checked before the first render, and each
// frame's are written as a set, so a failure leaves no new file of that
// frame and every old one as it was.
void checkOutputs(const RenderJob& job, const RenderCommandOptions& o) {
  if (o.writeExr) checkOutputPath("-o", job.exr);
  if (job.png.empty()) return;
  checkOutputPath(o.pngFlag, job.png);
  if (o.writeExr && namesSameFile(job.png, job.exr))
    throw OutputError("--png '" + job.png + "': names the same file as -o");
  checkOutputExtension(o.pngFlag, job.png, ".png");
}

// The scene with its edits, refused before any render when an output of
// `jobs` is one of the files it reads (its file, materials, meshes, images).
scene::Scene loadSceneOfOtherFiles(const RenderCommandOptions& o, const std::vector<RenderJob>& jobs) {
  const scene::InputFileLog inputs;
  scene::Scene scene = loadEditedScene(o.scene, o.edits);
  for (const RenderJob& job : jobs) {
    if (o.writeExr) checkNotAnInput("-o", job.exr, inputs.files());
    if (!job.png.empty()) checkNotAnInput(o.pngFlag, job.png, inputs.files());
  }
  return scene;
}

// The scene's sampling in --json: its stated samples per pixel, or
// "adaptive" or "chosen".
nlohmann::json samplingJson(const scene::RenderSettings& render) {
  switch (render.sampling) {
    case scene::Sampling::OnePass:
      return render.samplesPerPixel;
    case scene::Sampling::Adaptive:
      return "adaptive";
    case scene::Sampling::Chosen:
      return "chosen";
  }
  return nullptr;
}

// --noise-threshold and --max-spp ask for adaptive rounds, --spp for one
// pass; either wins over the scene file's render block, and not both.
void applySampling(const RenderCommandOptions& o, scene::Scene& scene) {
  const SamplingFlags& f = o.sampling;
  const std::optional<int>& spp = o.scene_overrides.spp;
  if (spp && (f.noiseThreshold || f.maxSpp))
    throw std::invalid_argument(std::string(f.noiseThreshold ? "--noise-threshold" : "--max-spp") +
                                ": asks for adaptive rounds, and --spp for one pass of " + std::to_string(*spp) +
                                " samples: give one or the other");
  if (f.noiseThreshold) {
    scene.render.noiseThreshold = checkedNoiseThreshold(*f.noiseThreshold);
    scene.render.sampling = scene::Sampling::Adaptive;
  }
  if (f.maxSpp) {
    scene.render.maxSamplesPerPixel = checkedMaxSpp(*f.maxSpp);
    scene.render.sampling = scene::Sampling::Adaptive;
  }
  if (!f.timeLimit) return;
  checkedTimeLimit(*f.timeLimit);
  if (scene.render.sampling == scene::Sampling::OnePass)
    throw std::invalid_argument("--time-limit: caps adaptive rounds, and " +
                                std::string(spp ? "--spp" : "the scene's render.spp") +
                                " asks for one pass: leave the samples unsaid, or drop --time-limit");
}

// A job's EXR and PNG of `image`, the pixels of `window`, as a set.
void writeOutputs(const RenderCommandOptions& o, const RenderJob& job, const scene::Scene& scene, const Image& image,
                  const PixelRect& window, const PreviewOptions& preview, const std::string& settingsNote = {}) {
  std::vector<OutputFile> outputs;
  if (o.writeExr) {
    ExrOptions exr = exrOptions(scene, o.backend, window, o.exrFlags);
    exr.metadata.provenance.renderSettings += settingsNote;
    outputs.push_back(exrFile(job.exr, image, exr));
  }
  if (!job.png.empty()) outputs.push_back(pngFile(job.png, image, preview));
  writeAllOrNothing(outputs);
}

// The outputs record what was rendered, the chosen light transport and
// sampling too; the next frame chooses again, its camera its own.
void writeRendered(const RenderCommandOptions& o, const RenderJob& job, scene::Scene& scene,
                   const RenderReport& report, const PreviewOptions& preview) {
  const scene::RenderSettings render = scene.render;
  const std::optional<scene::Environment> environment = scene.environment;
  scene::applyLightTransport(report.lightTransport, scene);
  scene::chooseSampling(scene);
  writeOutputs(o, job, scene, report.image, report.window, preview);
  scene.render = render;
  scene.environment = environment;
}

void runWatch(const RenderCommandOptions& o) {
  const PreviewOptions preview = chosenPreview(o.preview);
  const RenderJob job{std::nullopt, o.exr, o.png};
  checkOutputs(job, o);
  chosenExrLayers(o.exrFlags);
  const Backend backend = o.backend == "cpu" ? Backend::Cpu : Backend::Gpu;
  const unsigned threads = chosenThreads(o.farm);
  if (backend == Backend::Gpu) limitLavapipeThreads(threads);
  std::set<std::string> warned;  // each warning once, not on every load
  WatchedScene watched;
  watched.load = [&] {
    scene::Scene scene = loadSceneOfOtherFiles(o, {job});
    applySceneOverrides(o.scene_overrides, scene);
    // The watch refines each picture by its own passes (watch.h).
    scene.render.sampling = scene::Sampling::OnePass;
    checkImagesFitInMemory(scene, 1, o.scene_overrides.size.empty() ? o.scene + ": image size" : "--size");
    std::vector<std::string> fresh;
    for (const std::string& warning : sceneWarnings(scene))
      if (warned.insert(warning).second) fresh.push_back(warning);
    printWarnings(fresh, o.farm.quiet);
    return scene;
  };
  watched.write = [&](const scene::Scene& scene, const Image& image, int passes, int samples) {
    checkOutputs(job, o);  // again before each write: an output may have become a link meanwhile
    writeOutputs(o, job, scene, image, PixelRect::whole(image.width, image.height), preview,
                 " watchPasses=" + std::to_string(passes) + " watchSpp=" + std::to_string(samples));
  };
  Renderer renderer(o.adapter);
  watchScene(renderer, backend, threads, watched, o.watch, o.farm.quiet);
}

void runRender(const RenderCommandOptions& o) {
  const PreviewOptions preview = chosenPreview(o.preview);
  const std::vector<RenderJob> jobs = renderJobs(o);
  for (const RenderJob& job : jobs) checkOutputs(job, o);
  chosenExrLayers(o.exrFlags);
  scene::Scene scene = loadSceneOfOtherFiles(o, jobs);
  applySceneOverrides(o.scene_overrides, scene);
  applySampling(o, scene);
  const int width = scene.render.width, height = scene.render.height;
  const std::optional<PixelRect> crop = chosenCrop(o.farm, width, height);
  checkImagesFitInMemory(scene, 1, o.scene_overrides.size.empty() ? o.scene + ": image size" : "--size", crop);
  std::vector<std::string> warnings = sceneWarnings(scene);
  if (o.farm.seedsGiven && !scene.environment) warnings.push_back(seedChangesNothing("--seeds " + o.farm.seeds));
  printWarnings(warnings, o.farm.quiet || o.farm.json);
  const Backend backend = o.backend == "cpu" ? Backend::Cpu : Backend::Gpu;
  const unsigned threads = chosenThreads(o.farm);
  if (backend == Backend::Gpu) limitLavapipeThreads(threads);

  // Every frame is made from the scene as loaded; a still renders it as it is.
  const bool frames = std::any_of(jobs.begin(), jobs.end(), [](const RenderJob& job) { return job.frame; });
  const std::optional<scene::Scene> still = frames ? std::optional(scene) : std::nullopt;
  for (const RenderJob& job : jobs)  // every frame's camera before the first render
    if (job.frame) frameCamera(still->camera, still->cameraKeys, *job.frame);
  Renderer renderer(o.adapter);
  nlohmann::json summary = {{"backend", o.backend},
                            {"width", width},
                            {"height", height},
                            {"spp", samplingJson(scene.render)},
                            {"lighting", lightingName(scene)},
                            {"warnings", warnings},
                            {"renders", nlohmann::json::array()}};
  for (const RenderJob& job : jobs) {
    if (job.frame) scene = frameScene(*still, o.farm, *job.frame);
    if (job.seed && scene.environment) scene.environment->seed = *job.seed;
    const auto start = std::chrono::steady_clock::now();
    ProgressLog progress(job.frame  ? "frame " + std::to_string(*job.frame)
                         : job.seed ? "seed " + std::to_string(*job.seed)
                                    : std::string("rendering"),
                         o.farm.quiet || o.farm.json);
    AdaptiveReport rounds;
    const RenderReport report = renderPicture(renderer, scene, backend, std::ref(progress), {crop, threads},
                                              o.sampling.timeLimit.value_or(kNoTimeLimit), &rounds);
    progress.finish();
    const AdaptiveReport* adaptive = report.samplesPerPixel == 0 ? &rounds : nullptr;
    const double wallMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    writeRendered(o, job, scene, report, preview);

    summary["adapter"] = report.device;
    summary["renders"].push_back(renderJson(report, adaptive, job, wallMilliseconds));
    if (o.farm.quiet || o.farm.json) continue;
    if (o.verbose)
      printSummary(scene, report, adaptive, job, wallMilliseconds);
    else
      printSummaryLine(scene, report, adaptive, job, wallMilliseconds);
  }
  summary["peak_resident_bytes"] = peakResidentBytes();
  if (o.farm.json) std::printf("%s\n", summary.dump(2).c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderCommandOptions>();
  auto* c = app.add_subcommand("render", "Render a scene (.json), a control cage (.obj) or a glTF file");
  c->add_option("scene", o->scene, "Scene file")->required()->check(CLI::ExistingFile);
  auto* output = c->add_option(
      "-o,--output", o->output,
      "An .exr with the beauty and the --aovs layers, or a .png preview ('#' for the frame or seed number)");
  c->add_option("--png", o->png, "An 8-bit sRGB preview, beside -o's EXR or alone");
  addPreviewOptions(*c, o->preview);
  addSceneEditOptions(*c, o->edits);
  addSceneOverrideOptions(*c, o->scene_overrides);
  c->add_option("--noise-threshold", o->sampling.noiseThreshold,
                "Adaptive rounds stop a tile once its relative standard error is below this (default: the scene's "
                "render.noise_threshold, else 0.02; the default sampling where --spp and render.spp are unsaid)");
  c->add_option("--max-spp", o->sampling.maxSpp,
                "Adaptive rounds take at most this many camera samples per pixel (default: the scene's "
                "render.max_spp, else 256)");
  c->add_option("--time-limit", o->sampling.timeLimit,
                "Seconds of adaptive rounds after which no round starts (default: none, so the picture follows from "
                "the scene alone)");
  addFarmOptions(*c, o->farm);
  addExrOptions(*c, o->exrFlags);
  addWatchOptions(*c, o->watch);
  c->add_option("--backend", o->backend, "Renderer backend: the GPU kernels or the CPU reference")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  c->add_option("--adapter", o->adapter, "GPU adapter: a substring of its name (default: FACET_ADAPTER or the first)");
  c->add_flag("--verbose", o->verbose,
              "After each render, the objects' refinement, the lighting, every stage's time and the rays per bounce");
  c->callback([o, output, c] {
    checkWatchFlags(*c, o->watch, o->farm);
    chooseOutputs(*o, output->count() > 0);
    if (o->watch.watch)
      runWatch(*o);
    else
      runRender(*o);
  });
}

}  // namespace facet::cli

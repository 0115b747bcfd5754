// facet render: a scene file (or a bare cage) to EXR with every AOV, and a PNG preview.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "commands.h"
#include "engine/image/image_io.h"
#include "engine/renderer.h"
#include "scene_options.h"
#include "scenes/scene_file.h"

namespace facet::cli {
namespace {

struct RenderOptions {
  std::string scene;
  std::string exr;
  std::string png;
  float exposure = 0;
  SceneOverrides scene_overrides;
  std::string backend = "gpu";
  std::string adapter;
};

// Every output is checked before the render and written as a set, so a
// failure leaves no new file and every old one as it was.
void checkOutputs(const RenderOptions& o) {
  checkOutputPath("-o", o.exr);
  if (o.png.empty()) return;
  checkOutputPath("--png", o.png);
  if (std::filesystem::absolute(o.png).lexically_normal() == std::filesystem::absolute(o.exr).lexically_normal())
    throw OutputError("--png '" + o.png + "': names the same file as -o");
}

void runRender(const RenderOptions& o) {
  checkOutputs(o);
  scene::Scene scene = scene::loadScene(o.scene);
  applySceneOverrides(o.scene_overrides, scene);
  checkImagesFitInMemory(scene, 1, o.scene_overrides.size.empty() ? o.scene + ": image size" : "--size");
  if (scene.environment && scene.environment->map->clampedTexels > 0)
    std::fprintf(stderr, "warning: %s: %zu texels were negative, NaN or Inf and are set to 0\n",
                 scene.environment->map->source.c_str(), scene.environment->map->clampedTexels);
  const bool interactive = isatty(STDERR_FILENO);
  auto progress = [&](double done) {
    if (interactive) std::fprintf(stderr, "\rrendering %3d%%", int(done * 100));
  };
  const auto start = std::chrono::steady_clock::now();
  RenderReport report = render(scene, o.backend == "cpu" ? Backend::Cpu : Backend::Gpu, progress, o.adapter);
  const double wallMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (interactive) std::fprintf(stderr, "\r              \r");

  std::vector<OutputFile> outputs{exrFile(o.exr, report.image)};
  if (!o.png.empty()) outputs.push_back(pngFile(o.png, report.image, o.exposure));
  writeAllOrNothing(outputs);

  std::printf("%s\n", report.geometrySummary.c_str());
  if (scene.environment) std::printf("%s\n", describeEnvironment(*scene.environment).c_str());
  std::printf("backend: %s; %dx%d, %d spp, %s intersection\n", report.device.c_str(), scene.render.width,
              scene.render.height, scene.render.samplesPerPixel,
              scene.render.method == scene::IntersectionMethod::Exact ? "exact" : "tessellated");
  for (const StageTime& stage : report.stages)
    std::printf("  %-16s %8.1f ms\n", stage.name.c_str(), stage.milliseconds);
  std::printf("  %-16s %8.1f ms (wall clock, everything)\n", "total", wallMilliseconds);
  // Every stage after refinement casts or shades rays.
  const double traceSeconds = (report.totalMilliseconds() - report.stages.front().milliseconds) * 1e-3;
  std::printf("rays: %llu primary, %llu shadow, %.2f Mrays/s\n", (unsigned long long)report.primaryRays,
              (unsigned long long)report.shadowRays,
              double(report.primaryRays + report.shadowRays) / traceSeconds * 1e-6);
  if (report.cells)
    std::printf("micro-grid: %llu cells, %llu exact fallbacks, %.1f MiB of GPU arrays\n",
                (unsigned long long)report.cells, (unsigned long long)report.newtonFallbacks,
                double(report.gpuBytes) / (1 << 20));
  std::printf("wrote %s%s%s\n", o.exr.c_str(), o.png.empty() ? "" : " and ", o.png.c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* c = app.add_subcommand("render", "Render a scene (.json), a control cage (.obj) or a glTF file");
  c->add_option("scene", o->scene, "Scene file")->required()->check(CLI::ExistingFile);
  c->add_option("-o,--output", o->exr, "EXR with beauty and every AOV")->required();
  c->add_option("--png", o->png, "Also write an 8-bit sRGB preview");
  c->add_option("--exposure", o->exposure, "PNG exposure in stops");
  addSceneOverrideOptions(*c, o->scene_overrides);
  c->add_option("--backend", o->backend, "Renderer backend: the GPU kernels or the CPU reference")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  c->add_option("--adapter", o->adapter, "GPU adapter: a substring of its name (default: FACET_ADAPTER or the first)");
  c->callback([o] { runRender(*o); });
}

}  // namespace facet::cli

// facet render: a scene file (or a bare cage) to EXR with every AOV, and a PNG preview.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "commands.h"
#include "engine/image/image_io.h"
#include "engine/renderer.h"
#include "scenes/scene_file.h"

namespace facet::cli {
namespace {

struct RenderOptions {
  std::string scene;
  std::string exr;
  std::string png;
  std::string size;
  std::vector<double> eye, target, up;
  std::optional<double> fov;
  std::string method;
  std::optional<int> tessLevel;
  std::optional<int> spp;
  std::string subdivision;
  std::string backend = "gpu";
  std::string adapter;
  float exposure = 0;
  std::string environment;
  std::optional<double> environmentIntensity;
  std::optional<double> environmentRotation;
  std::string ibl;
  std::optional<int> iblSamples;
  std::string occlusion;
};

}  // namespace

void applyImageSize(const std::string& size, scene::Scene& scene) {
  int w = 0, h = 0;
  char x = 0, trailing = 0;
  if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &trailing) != 3 || x != 'x' || w < 1 || h < 1 || w > 16384 ||
      h > 16384)
    throw std::invalid_argument("--size '" + size + "': expected WIDTHxHEIGHT, each in 1..16384, e.g. 512x512");
  scene.render.width = w;
  scene.render.height = h;
}

void applyMethod(const std::string& method, scene::Scene& scene) {
  scene.render.method = method == "tess" ? scene::IntersectionMethod::Tessellated : scene::IntersectionMethod::Exact;
}

namespace {

glm::dvec3 vector3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// --env replaces the scene's map and keeps its other settings; the other
// environment flags need an environment from either.
void applyEnvironmentOverrides(const RenderOptions& o, scene::Scene& scene) {
  if (!o.environment.empty()) {
    if (!scene.environment) scene.environment.emplace();
    scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(o.environment));
  }
  const bool anyEnvironmentFlag =
      o.environmentIntensity || o.environmentRotation || !o.ibl.empty() || o.iblSamples || !o.occlusion.empty();
  if (!anyEnvironmentFlag) return;
  if (!scene.environment)
    throw std::invalid_argument(
        "--env-intensity, --env-rotation, --ibl, --ibl-samples and --occlusion need an environment: give --env FILE "
        "or an \"environment\" block in the scene");
  scene::Environment& e = *scene.environment;
  // CLI11's ranges let NaN through (every comparison with it is false).
  for (const auto& [flag, value] :
       {std::pair{"--env-intensity", o.environmentIntensity}, std::pair{"--env-rotation", o.environmentRotation}})
    if (value && !std::isfinite(*value)) throw std::invalid_argument(std::string(flag) + ": must be a finite number");
  if (o.environmentIntensity) e.intensity = *o.environmentIntensity;
  if (o.environmentRotation) e.rotationDegrees = *o.environmentRotation;
  if (!o.ibl.empty()) e.method = o.ibl == "sampled" ? scene::IblMethod::Sampled : scene::IblMethod::Prefiltered;
  if (o.iblSamples) e.samples = *o.iblSamples;
  if (!o.occlusion.empty()) e.occlusion = o.occlusion == "on";
}

// Command-line settings win over the scene file's.
void applyOverrides(const RenderOptions& o, scene::Scene& scene) {
  if (!o.size.empty()) applyImageSize(o.size, scene);
  if (!o.eye.empty()) scene.camera.eye = vector3(o.eye);
  if (!o.target.empty()) scene.camera.target = vector3(o.target);
  if (!o.up.empty()) scene.camera.up = vector3(o.up);
  if (o.fov) scene.camera.verticalFovDegrees = *o.fov;
  const glm::dvec3 view = scene.camera.target - scene.camera.eye;
  if (glm::length(view) == 0) throw std::invalid_argument("--eye and --target must differ");
  if (glm::length(glm::cross(view, scene.camera.up)) <= 1e-12 * glm::length(view) * glm::length(scene.camera.up))
    throw std::invalid_argument("--up must not be zero or parallel to the view direction");
  if (!o.subdivision.empty()) scene::overrideSubdivision(scene, o.subdivision, "--subdivision");
  if (!o.method.empty()) applyMethod(o.method, scene);
  if (o.tessLevel) scene.render.tessellationRate = *o.tessLevel;
  if (o.spp) {
    if (!scene::isSquare(*o.spp))
      throw std::invalid_argument("--spp " + std::to_string(*o.spp) + ": " + scene::kSamplesPerPixelRule);
    scene.render.samplesPerPixel = *o.spp;
  }
  applyEnvironmentOverrides(o, scene);
}

std::string describeEnvironment(const scene::Environment& e) {
  const std::string source = e.map->source.empty() ? "constant colour" : e.map->source.string();
  std::string text =
      "environment: " + source + " (" + std::to_string(e.map->width) + "x" + std::to_string(e.map->height) + "), " +
      (e.method == scene::IblMethod::Sampled ? "sampled, " + std::to_string(e.samples) +
                                                   " pairs per camera sample, occlusion " + (e.occlusion ? "on" : "off")
                                             : std::string("prefiltered"));
  return text;
}

void runRender(const RenderOptions& o) {
  scene::Scene scene = scene::loadScene(o.scene);
  applyOverrides(o, scene);
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

  writeExr(o.exr, report.image);
  if (!o.png.empty()) writePng(o.png, report.image, o.exposure);

  std::printf("%s\n", report.geometrySummary.c_str());
  if (scene.environment) std::printf("%s\n", describeEnvironment(*scene.environment).c_str());
  std::printf("backend: %s; %dx%d, %d spp, %s intersection\n", report.device.c_str(), scene.render.width,
              scene.render.height, scene.render.samplesPerPixel,
              scene.render.method == scene::IntersectionMethod::Exact ? "exact" : "tessellated");
  for (const StageTime& stage : report.stages)
    std::printf("  %-14s %10.1f ms\n", stage.name.c_str(), stage.milliseconds);
  std::printf("  %-14s %10.1f ms (wall clock, everything)\n", "total", wallMilliseconds);
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
  c->add_option("--size", o->size, "Image size WIDTHxHEIGHT");
  auto triple = [&](const char* name, std::vector<double>& v, const char* help) {
    c->add_option(name, v, help)->delimiter(',')->expected(3)->check(CLI::Number);
  };
  triple("--eye", o->eye, "Camera position x,y,z");
  triple("--target", o->target, "Point the camera looks at x,y,z");
  triple("--up", o->up, "Camera up vector x,y,z");
  c->add_option("--fov", o->fov, "Vertical field of view in degrees")->check(CLI::Range(1e-3, 179.0));
  c->add_option(
      "--subdivision", o->subdivision,
      "Subdivision of every object, whatever the file chose: catmull-clark, or none (the polygons as authored); "
      "by default OBJ cages are subdivided and glTF meshes are not");
  c->add_option("--method", o->method, "Ray casting: exact limit surface, or tessellated")
      ->check(CLI::IsMember({"exact", "tess"}));
  c->add_option("--tess-level", o->tessLevel, "Dicing rate k (k x k per patch) for --method tess")
      ->check(CLI::Range(1, 256));
  c->add_option("--spp", o->spp, "Samples per pixel (a square number)")->check(CLI::Range(1, 4096));
  c->add_option("--env", o->environment, "Environment map (.exr or .hdr, equirectangular 2:1) lighting the scene")
      ->check(CLI::ExistingFile);
  c->add_option("--env-intensity", o->environmentIntensity, "Environment radiance scale")->check(CLI::Range(0.0, 1e30));
  c->add_option("--env-rotation", o->environmentRotation, "Environment rotation about +y, in degrees");
  c->add_option("--ibl", o->ibl, "Image-based lighting: Monte Carlo with MIS, or the prefiltered split sum")
      ->check(CLI::IsMember({"sampled", "prefiltered"}));
  c->add_option("--ibl-samples", o->iblSamples,
                "Sampled IBL: environment + BRDF sample pairs per camera sample (--spp camera samples per pixel)")
      ->check(CLI::Range(1, 16384));
  c->add_option("--occlusion", o->occlusion, "Sampled IBL: shadow rays towards the environment")
      ->check(CLI::IsMember({"on", "off"}));
  c->add_option("--backend", o->backend, "Renderer backend: the GPU kernels or the CPU reference")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  c->add_option("--adapter", o->adapter, "GPU adapter: a substring of its name (default: FACET_ADAPTER or the first)");
  c->callback([o] { runRender(*o); });
}

}  // namespace facet::cli

#include "render_summary.h"

#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "scene_options.h"
#include "scenes/studio_environment.h"

namespace facet::cli {
namespace {

std::vector<std::string> outputPaths(const RenderJob& job) {
  std::vector<std::string> paths;
  for (const std::string& path : {job.exr, job.png})
    if (!path.empty()) paths.push_back(path);
  return paths;
}

std::uint64_t continuationRays(const RenderReport& report) {
  std::uint64_t rays = 0;
  for (std::size_t bounce = 1; bounce < report.raysPerBounce.size(); ++bounce)
    rays += report.raysPerBounce[bounce].rays;
  return rays;
}

// Every stage but refinement and start-up casts or shades rays.
double raysPerSecond(const RenderReport& report) {
  double traceSeconds = 0;
  for (const StageTime& stage : report.stages)
    if (stage.stage != Stage::RefineBvh && !isStartup(stage.stage)) traceSeconds += stage.milliseconds * 1e-3;
  return double(report.primaryRays + report.shadowRays + continuationRays(report)) / traceSeconds;
}

void printRaysPerBounce(const RenderReport& report) {
  for (std::size_t bounce = 0; bounce < report.raysPerBounce.size(); ++bounce) {
    const cpu::BounceRays& rays = report.raysPerBounce[bounce];
    std::printf("  bounce %-2zu %llu %s rays (%llu hit), %llu shadow\n", bounce, (unsigned long long)rays.rays,
                bounce == 0 ? "camera" : "continuation", (unsigned long long)rays.hits,
                (unsigned long long)rays.shadowRays);
  }
}

void printReportWarnings(const RenderReport& report) {
  for (const std::string& warning : report.warnings) std::fprintf(stderr, "facet: warning: %s\n", warning.c_str());
}

}  // namespace

std::string describeSampling(const RenderReport& report, const AdaptiveReport* adaptive) {
  const std::string why = report.samplingNote.empty() ? "" : " (" + report.samplingNote + ")";
  if (!adaptive) return std::to_string(report.samplesPerPixel) + " spp" + why;
  const auto [fewest, most] = tileSppRange(*adaptive);
  char text[200];
  std::snprintf(text, sizeof text, "adaptive %d-%d spp (mean %.1f, %d rounds), noise %.3g (threshold %.3g), %s", fewest,
                most, adaptive->sppMean, adaptive->rounds, adaptive->maxError, adaptive->noiseThreshold,
                toString(adaptive->stop));
  return text + why;
}

std::string lightingName(const scene::Scene& scene) {
  return scene.environment && scene::isStudioEnvironment(*scene.environment) ? scene::kStudioEnvironmentName : "scene";
}

std::uint64_t peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

void printSummaryLine(const scene::Scene& scene, const RenderReport& report, const AdaptiveReport* adaptive,
                      const RenderJob& job, double wallMilliseconds) {
  printReportWarnings(report);
  double startupMilliseconds = 0, stageMilliseconds = 0;
  for (const StageTime& stage : report.stages)
    (isStartup(stage.stage) ? startupMilliseconds : stageMilliseconds) += stage.milliseconds;
  std::string line = "wrote " + CLI::detail::join(outputPaths(job), " and ") + ": " +
                     std::to_string(report.window.width()) + "x" + std::to_string(report.window.height()) + ", " +
                     describeSampling(report, adaptive) + ", " +
                     (scene.render.method == scene::IntersectionMethod::Exact ? "exact" : "tessellated");
  const int bounces = report.lightTransport.bounces;
  if (bounces > 0) line += ", " + std::to_string(bounces) + (bounces == 1 ? " bounce" : " bounces");
  // The rays each bounce cast, up to the last that cast any.
  std::size_t lastBounce = report.raysPerBounce.size();
  while (lastBounce > 1 && report.raysPerBounce[lastBounce - 1].rays == 0) --lastBounce;
  for (std::size_t bounce = 0; bounce < lastBounce; ++bounce)
    line += (bounce == 0 ? " (rays per bounce " : "/") + std::to_string(report.raysPerBounce[bounce].rays) +
            (bounce + 1 == lastBounce ? ")" : "");
  char timing[160];
  std::snprintf(timing, sizeof timing, "; %s; %.2f s (start-up %.2f s, stages %.2f s), %.2f Mrays/s",
                report.device.c_str(), wallMilliseconds * 1e-3, startupMilliseconds * 1e-3, stageMilliseconds * 1e-3,
                raysPerSecond(report) * 1e-6);
  line += timing;
  // What facet added or left out is named, never only in --verbose.
  if (scene.environment && scene::isStudioEnvironment(*scene.environment))
    line += std::string("; lit by the ") + scene::kStudioEnvironmentName + " (the scene has no lights or environment)";
  if (!report.lightTransport.note.empty()) line += "; " + report.lightTransport.note;
  std::printf("%s\n", line.c_str());
}

void printSummary(const scene::Scene& scene, const RenderReport& report, const AdaptiveReport* adaptive,
                  const RenderJob& job, double wallMilliseconds) {
  printReportWarnings(report);
  std::printf("%s\n", report.geometrySummary.c_str());
  if (scene.environment && scene::isStudioEnvironment(*scene.environment))
    std::printf("lighting: %s (the scene has no lights or environment)\n", scene::kStudioEnvironmentName);
  if (scene.environment) std::printf("%s\n", describeEnvironment(*scene.environment).c_str());
  std::printf("backend: %s; %dx%d, %s, %s intersection\n", report.device.c_str(), scene.render.width,
              scene.render.height, describeSampling(report, adaptive).c_str(),
              scene.render.method == scene::IntersectionMethod::Exact ? "exact" : "tessellated");
  if (!(report.window == PixelRect::whole(scene.render.width, scene.render.height)))
    std::printf("crop: %s (%dx%d pixels)\n", report.window.text().c_str(), report.window.width(),
                report.window.height());
  for (const StageTime& stage : report.stages)
    std::printf("  %-16s %8.1f ms\n", std::string(stageName(stage.stage)).c_str(), stage.milliseconds);
  std::printf("  %-16s %8.1f ms (wall clock, everything)\n", "total", wallMilliseconds);
  std::printf("rays: %llu primary, %llu shadow, %.2f Mrays/s\n", (unsigned long long)report.primaryRays,
              (unsigned long long)report.shadowRays, raysPerSecond(report) * 1e-6);
  printRaysPerBounce(report);
  if (report.cells)
    std::printf("micro-grid: %llu cells, %llu exact fallbacks, %.1f MiB of GPU arrays\n",
                (unsigned long long)report.cells, (unsigned long long)report.newtonFallbacks,
                double(report.gpuBytes) / (1 << 20));
  const std::vector<std::string> paths = outputPaths(job);
  std::printf("wrote %s\n", CLI::detail::join(paths, " and ").c_str());
}

nlohmann::json adaptiveJson(const AdaptiveReport& r) {
  const auto [fewest, most] = tileSppRange(r);
  return {{"rounds", r.rounds},
          {"samples", r.samples},
          {"spp_mean", r.sppMean},
          {"spp_min", fewest},
          {"spp_max", most},
          {"max_tile_error", r.maxError},
          {"noise_threshold", r.noiseThreshold},
          {"stop", toString(r.stop)}};
}

nlohmann::json stagesJson(const RenderReport& report) {
  nlohmann::json stages = nlohmann::json::object();
  for (const StageTime& stage : report.stages) stages[std::string(stageName(stage.stage))] = stage.milliseconds;
  return stages;
}

nlohmann::json renderJson(const RenderReport& report, const AdaptiveReport* adaptive, const RenderJob& job,
                          double wallMilliseconds) {
  nlohmann::json render = {{"frame", job.frame ? nlohmann::json(*job.frame) : nlohmann::json()},
                           {"seed", job.seed ? nlohmann::json(*job.seed) : nlohmann::json()},
                           {"crop", {report.window.x0, report.window.y0, report.window.x1, report.window.y1}},
                           {"stages_ms", stagesJson(report)},
                           {"wall_ms", wallMilliseconds},
                           {"primary_rays", report.primaryRays},
                           {"shadow_rays", report.shadowRays},
                           {"rays_per_second", raysPerSecond(report)},
                           {"gpu_bytes", report.gpuBytes},
                           {"outputs", outputPaths(job)}};
  if (adaptive)
    render["adaptive"] = adaptiveJson(*adaptive);
  else
    render["spp"] = report.samplesPerPixel;
  if (!report.samplingNote.empty()) render["sampling"] = report.samplingNote;
  render["bounces"] = report.lightTransport.bounces;
  if (!report.lightTransport.note.empty()) render["light_transport"] = report.lightTransport.note;
  if (!report.warnings.empty()) render["warnings"] = report.warnings;
  if (report.raysPerBounce.empty()) return render;
  nlohmann::json bounces = nlohmann::json::array();
  for (const cpu::BounceRays& rays : report.raysPerBounce)
    bounces.push_back({{"rays", rays.rays}, {"hits", rays.hits}, {"shadow_rays", rays.shadowRays}});
  render["rays_per_bounce"] = bounces;
  return render;
}

}  // namespace facet::cli

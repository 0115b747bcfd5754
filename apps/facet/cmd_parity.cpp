// facet parity: render a scene on both backends and compare them AOV by AOV
// (analysis/parity.h); exits with kCheckFailed above tolerance.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "analysis/parity.h"
#include "commands.h"
#include "engine/image/image_io.h"
#include "engine/renderer.h"
#include "exit_codes.h"
#include "scene_options.h"
#include "scenes/scene_file.h"

namespace facet::cli {
namespace {

using analysis::AovParity;
using analysis::ParityReport;

struct ParityOptions {
  std::string scene;
  std::string size;
  std::string method;
  std::string subdivision;
  std::string energyCompensation;
  std::optional<int> bounces;
  std::string heatmap;
  std::string adapter;
  bool json = false;
};

nlohmann::json toJson(const ParityReport& report, const RenderReport& cpu, const RenderReport& gpu) {
  nlohmann::json aovs = nlohmann::json::array();
  for (const AovParity& a : report.aovs)
    aovs.push_back({{"name", a.name},
                    {"relative", a.unit},
                    {"maxAbsolute", a.maxAbsolute},
                    {"meanAbsolute", a.meanAbsolute},
                    {"maxRelative", a.maxRelative},
                    {"meanRelative", a.meanRelative},
                    {"tolerance", a.tolerance},
                    {"overSilhouette", a.overSilhouette},
                    {"overInterior", a.overInterior},
                    {"shareOver", a.shareOver},
                    {"pass", a.pass}});
  auto milliseconds = [](const RenderReport& r) {
    nlohmann::json stages = nlohmann::json::object();
    for (const StageTime& s : r.stages) stages[std::string(stageName(s.stage))] = s.milliseconds;
    return stages;
  };
  return {{"width", report.width},
          {"height", report.height},
          {"pixels", report.pixels},
          {"coveredOnBoth", report.covered},
          {"silhouettePixels", report.silhouettePixels},
          {"coverage",
           {{"mismatches", report.coverageMismatches},
            {"mismatchesOffSilhouette", report.coverageMismatchesInterior},
            {"pass", report.coveragePass}}},
          {"aovs", aovs},
          {"cpu", {{"device", cpu.device}, {"milliseconds", milliseconds(cpu)}}},
          {"gpu", {{"device", gpu.device}, {"milliseconds", milliseconds(gpu)}}},
          {"pass", report.pass}};
}

void runParity(const ParityOptions& o) {
  if (!o.heatmap.empty()) checkOutputPath("--heatmap", o.heatmap);
  scene::Scene scene = scene::loadScene(o.scene);
  if (!o.size.empty()) applyImageSize(o.size, scene);
  if (!o.method.empty()) applyMethod(o.method, scene);
  if (!o.subdivision.empty()) scene::overrideSubdivision(scene, o.subdivision, "--subdivision");
  applyEnergyCompensation(o.energyCompensation, scene);
  if (o.bounces) scene.render.bounces = *o.bounces;
  // Both backends' images, and the heat map's when one is asked for.
  checkImagesFitInMemory(scene, o.heatmap.empty() ? 2 : 3, o.size.empty() ? o.scene + ": image size" : "--size");
  const RenderReport cpu = render(scene, Backend::Cpu);
  const RenderReport gpu = render(scene, Backend::Gpu, {}, o.adapter);
  const ParityReport report = analysis::compareImages(cpu.image, gpu.image);
  if (!o.heatmap.empty()) analysis::writeHeatmap(o.heatmap, report);
  if (o.json) {
    std::printf("%s\n", toJson(report, cpu, gpu).dump(2).c_str());
  } else {
    std::printf("%s: %s intersection; CPU: %s; GPU: %s\n", o.scene.c_str(),
                scene.render.method == scene::IntersectionMethod::Exact ? "exact" : "tessellated", cpu.device.c_str(),
                gpu.device.c_str());
    std::printf("%s", analysis::describe(report).c_str());
    if (!o.heatmap.empty()) std::printf("wrote %s\n", o.heatmap.c_str());
  }
  if (!report.pass) throw CheckFailed("parity: " + o.scene + " is out of tolerance");
}

}  // namespace

void addParityCommand(CLI::App& app) {
  auto o = std::make_shared<ParityOptions>();
  auto* c = app.add_subcommand("parity", "Render a scene on the GPU and the CPU reference and compare every AOV");
  c->add_option("scene", o->scene, "Scene file (.json, .obj cage or glTF)")->required()->check(CLI::ExistingFile);
  c->add_option("--size", o->size, "Image size WIDTHxHEIGHT");
  c->add_option("--method", o->method, "Ray casting: exact limit surface, or tessellated")
      ->check(CLI::IsMember({"exact", "tess"}));
  c->add_option(
      "--subdivision", o->subdivision,
      "Subdivision of every object, whatever the file chose: catmull-clark, or none (the polygons as authored)");
  addEnergyCompensationOption(*c, o->energyCompensation);
  c->add_option("--bounces", o->bounces, "Continuations of each camera sample's path")
      ->check(CLI::Range(0, scene::kMaxBounces));
  c->add_option("--heatmap", o->heatmap, "Write the per-pixel error (in units of tolerance) as a PNG");
  c->add_option("--adapter", o->adapter, "GPU adapter: a substring of its name");
  c->add_flag("--json", o->json, "Machine-readable report");
  c->callback([o] { runParity(*o); });
}

}  // namespace facet::cli

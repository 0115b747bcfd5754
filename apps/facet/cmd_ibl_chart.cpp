// facet ibl-chart: error against time of sampled, filtered and prefiltered
// image-based lighting, and the camera samples' convergence
// (analysis/ibl_chart.h).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/ibl_chart.h"
#include "commands.h"
#include "engine/image/output_folder.h"
#include "data_folder.h"
#include "material_options.h"
#include "scene_options.h"
#include "scene_warnings.h"
#include "scenes/light_transport.h"

namespace facet::cli {
namespace {

struct ChartOptions {
  std::string output;
  std::string scene;                      // default: the preview in dataFolder()
  std::vector<std::string> environments;  // default: courtyard and sunrise in dataFolder()
  std::string size = "128x64";
  std::string alphas = "0.05,0.25,0.6";
  int maxSamples = 4096;
  int repeats = 3;
  std::string backend = "gpu";
  std::string adapter;
  bool quick = false;
};

std::vector<double> parseAlphas(const std::string& text) {
  std::vector<double> alphas;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    const double alpha = parseNumber("--alphas", item);
    if (alpha < 0 || alpha > 1) throw std::invalid_argument("--alphas: each must be in [0, 1], got " + item);
    alphas.push_back(alpha);
  }
  if (alphas.empty()) throw std::invalid_argument("--alphas: give at least one alpha");
  return alphas;
}

std::vector<int> sampleCounts(int maxSamples) {
  std::vector<int> counts{1};
  while (counts.back() < maxSamples) counts.push_back(counts.back() * 4);
  if (counts.back() != maxSamples)
    throw std::invalid_argument("--max-samples " + std::to_string(maxSamples) +
                                ": must be a power of 4 (1, 4, 16, ...)");
  return counts;
}

void runIblChart(ChartOptions o) {
  if (o.scene.empty()) o.scene = dataFolder() / "scenes/examples/preview.json";
  if (o.environments.empty())
    for (const char* map : {"courtyard_256x128.hdr", "sunrise.exr"})
      o.environments.push_back(dataFolder() / "scenes/environments" / map);
  if (o.quick) {
    o.size = "48x24";
    o.alphas = "0.25";
    o.maxSamples = 16;
    o.repeats = 1;
  }
  analysis::IblChartSettings settings;
  settings.alphas = parseAlphas(o.alphas);
  settings.sampleCounts = sampleCounts(o.maxSamples);
  settings.base = scene::loadStatedScene(o.scene);
  printWarnings(sceneWarnings(settings.base), false);
  applyImageSize(o.size, settings.base);
  applyMethod("tess", settings.base);
  StagedOutputFolder folder(o.output);
  settings.output = folder.path();
  settings.environments.assign(o.environments.begin(), o.environments.end());
  settings.antialiasingSamples = o.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 4, 16, 64, 256};
  settings.repeats = o.repeats;
  settings.backend = o.backend == "cpu" ? Backend::Cpu : Backend::Gpu;
  Renderer renderer(o.adapter);
  analysis::writeIblChart(renderer, settings);
  folder.publish();
  std::printf(
      "wrote %s/ibl_chart.csv, ibl_chart.svg, ibl_chart.png, antialiasing.csv and a reference | prefiltered PNG per "
      "setup and alpha\n",
      o.output.c_str());
}

}  // namespace

void addIblChartCommand(CLI::App& app) {
  auto o = std::make_shared<ChartOptions>();
  auto* c = app.add_subcommand("ibl-chart",
                               "Error against time of sampled (N = 1, 4, 16, ...) and prefiltered image-based "
                               "lighting, per roughness and environment: CSV, chart, previews; and the camera "
                               "samples' error against samples per pixel");
  c->add_option("-o,--output", o->output, "Output folder")->required();
  c->add_option("--scene", o->scene,
                "Geometry and materials (its punctual lights are removed; default: the preview in share/facet)")
      ->check(CLI::ExistingFile);
  c->add_option("--envs", o->environments,
                "Environment maps, one chart panel each (default: courtyard and sunrise in share/facet)")
      ->delimiter(',')
      ->check(CLI::ExistingFile);
  c->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default 128x64)");
  c->add_option("--alphas", o->alphas, "Roughness alphas, each in [0, 1], set on every material: a,b,c");
  c->add_option("--max-samples", o->maxSamples,
                "Largest N, a power of 4 (default 4096); the reference is sampled with 4 x as many pairs")
      ->check(CLI::Range(1, 4096));
  c->add_option("--repeats", o->repeats, "Timed runs per point (the median is reported)")->check(CLI::Range(1, 100));
  c->add_option("--backend", o->backend, "Renderer backend: the GPU kernels or the CPU reference")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  c->add_option("--adapter", o->adapter, "GPU adapter: a substring of its name (default: FACET_ADAPTER or the first)");
  c->add_flag("--quick", o->quick, "Smoke test: 48x24, alpha 0.25, N up to 16, one run per point");
  c->callback([o] { runIblChart(*o); });
}

}  // namespace facet::cli

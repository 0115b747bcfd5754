// facet ibl-chart: error against time for the two image-based lighting
// methods, sampled at N = 1, 4, 16, ... pairs and the prefiltered split sum,
// per roughness, on each environment: a CSV, a gnuplot chart and previews.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "commands.h"
#include "engine/image/image_io.h"
#include "engine/renderer.h"
#include "gnuplot.h"
#include "material_options.h"
#include "scenes/scene_file.h"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

struct ChartOptions {
  std::string output;
  std::string scene = "scenes/examples/preview.json";
  std::vector<std::string> environments{"scenes/environments/courtyard_256x128.hdr", "scenes/environments/sunrise.exr"};
  std::string size = "128x64";
  std::string alphas = "0.05,0.25,0.6";
  int maxSamples = 4096;
  int repeats = 3;
  std::string backend = "gpu";
  std::string adapter;
  bool quick = false;
};

// The reference is sampled with this many times the largest N, so that its
// own noise is half the largest N's and the curve's tail stays meaningful.
constexpr int kReferenceFactor = 4;

struct Point {
  std::string setup;
  double alpha = 0;
  bool sampled = true;
  int samples = 0;
  double milliseconds = 0;
  double prepMilliseconds = 0;
  double relativeRmse = 0;
  double maxAbsError = 0;
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

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// Reference (left) and split sum (right) side by side, exposed so that the
// reference's mean covered radiance lands at middle grey.
void writeComparison(const fs::path& path, const Image& reference, const Image& prefiltered) {
  Image pair(2 * reference.width, reference.height);
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const std::size_t i = reference.index(x, y);
      pair.beauty[pair.index(x, y)] = reference.beauty[i];
      pair.beauty[pair.index(x + reference.width, y)] = prefiltered.beauty[i];
    }
  writePng(path, pair, bench::middleGreyExposure(reference));
}

void writeCsv(const fs::path& path, const std::vector<Point>& points) {
  std::vector<std::vector<std::string>> rows;
  for (const Point& p : points)
    rows.push_back({p.setup, formatNumber(p.alpha), p.sampled ? "sampled" : "prefiltered",
                    p.sampled ? std::to_string(p.samples) : "", formatNumber(p.milliseconds),
                    formatNumber(p.prepMilliseconds), formatNumber(p.relativeRmse), formatNumber(p.maxAbsError)});
  bench::writeCsv(
      path,
      {"setup", "alpha", "method", "samples", "milliseconds", "prep_milliseconds", "relative_rmse", "max_abs_error"},
      rows);
}

// One panel per setup; per alpha a colour, sampled as a line through its N
// points (N written beside the first alpha's), the split sum as one large
// marker of the same colour.
void writeChart(const fs::path& directory, const std::vector<std::string>& setups, const std::vector<double>& alphas,
                const std::vector<Point>& points, const std::string& subtitle) {
  std::ostringstream data, script;
  for (const std::string& setup : setups)
    for (double alpha : alphas)
      for (bool sampled : {true, false}) {
        for (const Point& p : points)
          if (p.setup == setup && p.alpha == alpha && p.sampled == sampled)
            data << p.milliseconds << " " << p.relativeRmse << " " << p.samples << "\n";
        data << "\n\n";
      }
  static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  script << "set output OUTPUT\n"
         << "set multiplot layout 1," << setups.size() << " title \"IBL error against time: sampled (lines, N pairs) "
         << "vs prefiltered split sum (squares)\\n"
         << subtitle << "\" noenhanced\n"
         << "set logscale xy\nset grid\nset format y '10^{%L}'\nset key bottom left box opaque font ',10'\n"
         << "set xlabel 'time per image (ms, GPU stages)'\nset ylabel 'relative RMSE vs reference'\n";
  std::size_t block = 0;
  for (const std::string& setup : setups) {
    script << "set title \"" << setup << "\" noenhanced\nplot ";
    for (std::size_t a = 0; a < alphas.size(); ++a, block += 2) {
      const char* colour = kColours[a % std::size(kColours)];
      const std::string label = formatNumber(alphas[a]);
      script << (a ? ", " : "") << "DATA index " << block << " using 1:2 with linespoints lw 2 pt 7 ps 0.8 lc rgb '"
             << colour << "' title 'sampled, alpha " << label << "', DATA index " << block + 1
             << " using 1:2 with points pt 5 ps 2 lc rgb '" << colour << "' title 'prefiltered, alpha " << label << "'";
      if (a == 0)
        script << ", DATA index " << block
               << " using 1:2:(sprintf('N=%d', $3)) with labels offset char 0,1 font ',8' notitle";
    }
    script << "\n";
  }
  script << "unset multiplot\n";
  const int width = 620 * int(setups.size()), height = 560;
  runGnuplot(script.str(), data.str(), directory / "ibl_chart.svg", width, height);
  runGnuplot(script.str(), data.str(), directory / "ibl_chart.png", width, height);
}

void runIblChart(ChartOptions o) {
  if (o.quick) {
    o.size = "48x24";
    o.alphas = "0.25";
    o.maxSamples = 16;
    o.repeats = 1;
  }
  const std::vector<double> alphas = parseAlphas(o.alphas);
  const std::vector<int> counts = sampleCounts(o.maxSamples);
  const int referenceSamples = kReferenceFactor * o.maxSamples;
  const Backend backend = o.backend == "cpu" ? Backend::Cpu : Backend::Gpu;

  scene::Scene base = scene::loadScene(o.scene);
  applyImageSize(o.size, base);
  applyMethod("tess", base);
  // The chart measures the environment term alone.
  base.lights.clear();
  if (!base.environment) base.environment.emplace();
  // The split sum has no visibility: without occlusion both methods
  // integrate the same unshadowed term, and the chart isolates the
  // integration error.
  base.environment->occlusion = false;
  fs::create_directories(o.output);

  std::vector<std::string> setups;
  std::vector<Point> points;
  for (const std::string& file : o.environments) {
    scene::Scene scene = base;
    scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(file));
    const std::string setup = fs::path(file).stem().string();
    setups.push_back(setup);
    for (double alpha : alphas) {
      for (materials::Material& material : scene.materials) material.alpha = alpha;
      auto renderWith = [&](scene::IblMethod method, int samples, Backend on) {
        scene.environment->method = method;
        scene.environment->samples = samples;
        return render(scene, on, {}, o.adapter);
      };
      // Its own random numbers: sharing the estimates' would under-report their error.
      scene.environment->seed = 1;
      const RenderReport reference = renderWith(scene::IblMethod::Sampled, referenceSamples, backend);
      scene.environment->seed = 0;
      // Untimed first runs: they compile each method's kernels and warm the
      // prefilter's disk cache.
      renderWith(scene::IblMethod::Sampled, 1, backend);
      const RenderReport firstPrefiltered = renderWith(scene::IblMethod::Prefiltered, 1, backend);
      std::printf("%s, alpha %g: reference N=%d %.0f ms; first prefiltered run: preparation %.1f ms\n", setup.c_str(),
                  alpha, referenceSamples, bench::traceMilliseconds(reference),
                  bench::preparationMilliseconds(firstPrefiltered));

      auto measure = [&](scene::IblMethod method, int samples) {
        std::vector<double> times, preparations;
        Image image;
        for (int r = 0; r < o.repeats; ++r) {
          RenderReport report = renderWith(method, samples, backend);
          times.push_back(bench::traceMilliseconds(report));
          preparations.push_back(bench::preparationMilliseconds(report));
          if (r == 0) image = std::move(report.image);
        }
        const bench::ImageError error = bench::compareToReference(image, reference.image);
        if (error.compared == 0) throw std::runtime_error("ibl-chart: the reference image covers no pixel");
        Point p{setup,
                alpha,
                method == scene::IblMethod::Sampled,
                samples,
                bench::median(times),
                bench::median(preparations),
                error.relativeRmse,
                error.maxAbsolute};
        std::printf("  %-18s %9.1f ms  (+%.1f ms preparation)  relative RMSE %.3g  max |error| %.3g\n",
                    p.sampled ? ("sampled N=" + std::to_string(samples)).c_str() : "prefiltered", p.milliseconds,
                    p.prepMilliseconds, p.relativeRmse, p.maxAbsError);
        std::fflush(stdout);
        points.push_back(p);
        return image;
      };
      for (int samples : counts) measure(scene::IblMethod::Sampled, samples);
      const Image prefiltered = measure(scene::IblMethod::Prefiltered, 1);
      writeComparison(fs::path(o.output) / (setup + "_alpha" + formatNumber(alpha) + ".png"), reference.image,
                      prefiltered);
    }
  }
  writeCsv(fs::path(o.output) / "ibl_chart.csv", points);
  const std::string subtitle = std::to_string(base.render.width) + "x" + std::to_string(base.render.height) + ", " +
                               toString(backend) + ", reference: sampled N=" + std::to_string(referenceSamples) +
                               ", occlusion off, no punctual lights";
  writeChart(o.output, setups, alphas, points, subtitle);
  std::printf(
      "wrote %s/ibl_chart.csv, ibl_chart.svg, ibl_chart.png and a reference | prefiltered PNG per setup and "
      "alpha\n",
      o.output.c_str());
}

}  // namespace

void addIblChartCommand(CLI::App& app) {
  auto o = std::make_shared<ChartOptions>();
  auto* c = app.add_subcommand("ibl-chart",
                               "Error against time of sampled (N = 1, 4, 16, ...) and prefiltered image-based "
                               "lighting, per roughness and environment: CSV, chart, previews");
  c->add_option("-o,--output", o->output, "Output folder")->required();
  c->add_option("--scene", o->scene, "Geometry and materials (its punctual lights are removed)")
      ->check(CLI::ExistingFile);
  c->add_option("--envs", o->environments, "Environment maps, one chart panel each")
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

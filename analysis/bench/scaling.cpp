// facet bench, section "scaling": time against resolution, patch count,
// light count and IBL samples on both backends, each series fitted with
// t = a x^b on log-log axes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/gnuplot.h"
#include "analysis/power_law.h"
#include "scenes/light_transport.h"

namespace facet::analysis::bench {
namespace {

namespace fs = std::filesystem;

struct SeriesSpec {
  Backend backend = Backend::Gpu;
  scene::IntersectionMethod method = scene::IntersectionMethod::Tessellated;
  std::string variant;  // what else tells series of one sweep apart (IBL: occlusion), or empty
  std::function<void(scene::Scene&)> configure = [](scene::Scene&) {};
  std::vector<int> steps;  // empty: the sweep's
};

struct SweepSpec {
  std::string name;    // CSV key and file stem
  std::string title;   // chart title
  std::string xLabel;  // chart axis and prose
  std::string fixed;   // what is held constant, for the chart and the report
  scene::Scene base;
  std::vector<int> steps;                         // the swept parameter
  std::function<void(scene::Scene&, int)> apply;  // sets one step on a copy of `base`
  std::function<double(int)> xOf = [](int step) { return double(step); };
  bool xIsPatches = false;  // x is what the renderer reports, not the step
  std::vector<SeriesSpec> series;
};

struct Series {
  std::string backend, method, variant;
  std::vector<double> x, milliseconds;
  PowerLawFit fit;

  std::string label() const { return backend + " " + method + (variant.empty() ? "" : ", " + variant); }
};

std::string methodName(scene::IntersectionMethod method) {
  return method == scene::IntersectionMethod::Exact ? "exact" : "tessellated";
}

// The fixed cost (dispatches, BVH root work, per-image setup) dominates the
// small end of every sweep and would flatten the slope; the asymptotic
// exponent is fitted on the upper half of the points only.
PowerLawFit fitUpperHalf(const std::vector<double>& x, const std::vector<double>& t) {
  return fitPowerLaw(x, t, x.size() > 2 ? x.size() / 2 : 0);
}

std::string fixed2(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

std::string exponentText(const PowerLawFit& fit) {
  return fixed2(fit.exponent) + (fit.points >= 3 ? " ± " + fixed2(fit.standardError) : "");
}

std::vector<Series> runSweep(Renderer& renderer, const SweepSpec& sweep, const BenchOptions& options) {
  std::vector<Series> result;
  for (const SeriesSpec& spec : sweep.series) {
    Series series{toString(spec.backend), methodName(spec.method), spec.variant, {}, {}, {}};
    auto sceneAt = [&](int step) {
      scene::Scene scene = sweep.base;
      scene.render.method = spec.method;
      spec.configure(scene);
      sweep.apply(scene, step);
      return scene;
    };
    for (int step : spec.steps.empty() ? sweep.steps : spec.steps) {
      const scene::Scene scene = sceneAt(step);
      // Untimed: lavapipe JITs a pipeline on first use, and some stage
      // kernels are specialised per configuration (light count, for one).
      if (spec.backend == Backend::Gpu) renderer.render(scene, spec.backend);
      double x = sweep.xOf(step);
      const double ms = medianMilliseconds(options.repeats, [&] {
        const RenderReport report = renderer.render(scene, spec.backend);
        if (sweep.xIsPatches) x = report.patches;
        return traceMilliseconds(report);
      });
      series.x.push_back(x);
      series.milliseconds.push_back(ms);
      std::printf("scaling %-11s %-28s x=%-8g %10.2f ms\n", sweep.name.c_str(), series.label().c_str(), x, ms);
      std::fflush(stdout);
    }
    series.fit = fitUpperHalf(series.x, series.milliseconds);
    result.push_back(std::move(series));
  }
  return result;
}

// Points joined by a solid line, the fit as a dashed line of the same colour
// over the range it was fitted on; the legend carries the exponent.
void writeChart(const fs::path& directory, const SweepSpec& sweep, const std::vector<Series>& series) {
  static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  std::ostringstream data, script;
  script << "set output OUTPUT\nset logscale xy\nset grid\nset key top left box opaque font ',10' noenhanced\n"
         << "set title \"" << sweep.title << "\\n"
         << sweep.fixed << "\" noenhanced\n"
         << "set xlabel '" << sweep.xLabel << "' noenhanced\n"
         << "set ylabel 'time per image (ms, trace + shade stages)'\nplot ";
  for (std::size_t s = 0; s < series.size(); ++s) {
    const Series& line = series[s];
    for (std::size_t i = 0; i < line.x.size(); ++i) data << line.x[i] << " " << line.milliseconds[i] << "\n";
    data << "\n\n";
    for (double x : {line.fit.xFirst, line.fit.xLast})
      data << x << " " << line.fit.coefficient * std::pow(x, line.fit.exponent) << "\n";
    data << "\n\n";
    const char* colour = kColours[s % std::size(kColours)];
    const int pointType = line.backend == "gpu" ? 7 : 5;
    script << (s ? ", " : "") << "DATA index " << 2 * s << " using 1:2 with linespoints lw 2 pt " << pointType
           << " ps 0.9 lc rgb '" << colour << "' title '" << line.label() << " (b = " << fixed2(line.fit.exponent)
           << ")', DATA index " << 2 * s + 1 << " using 1:2 with lines dt 2 lw 2 lc rgb '" << colour << "' notitle";
  }
  script << "\n";
  runGnuplot(script.str(), data.str(), directory / (sweep.name + ".svg"), 800, 600);
  runGnuplot(script.str(), data.str(), directory / (sweep.name + ".png"), 800, 600);
}

// From the fitted numbers: the range of exponents per sweep, then the GPU
// against the CPU at the largest point measured on both.
std::string describe(const std::vector<SweepSpec>& sweeps, const std::vector<std::vector<Series>>& results) {
  std::string text;
  for (std::size_t w = 0; w < sweeps.size(); ++w) {
    const auto& series = results[w];
    const auto [low, high] = std::minmax_element(
        series.begin(), series.end(), [](const Series& a, const Series& b) { return a.fit.exponent < b.fit.exponent; });
    text += "Against " + sweeps[w].xLabel + ", the fitted exponents run from " + fixed2(low->fit.exponent) + " (" +
            low->label() + ") to " + fixed2(high->fit.exponent) + " (" + high->label() + "). ";
  }
  const auto& resolution = results.front();
  for (const Series& gpu : resolution) {
    if (gpu.backend != "gpu") continue;
    for (const Series& cpu : resolution)
      if (cpu.backend == "cpu" && cpu.method == gpu.method && cpu.variant == gpu.variant &&
          cpu.x.back() == gpu.x.back())
        text += "At " + cell(gpu.x.back()) + " pixels the GPU path takes " +
                fixed2(gpu.milliseconds.back() / cpu.milliseconds.back()) + "x the CPU reference's time (" +
                gpu.method + "). ";
  }
  text.pop_back();
  return text;
}

scene::Light pointLight(int index, int count) {
  // A ring in front of the objects, so that every light reaches the visible
  // faces and each adds its shadow rays; c_light shrinks with the count so
  // the image stays exposed alike.
  const double angle = 2 * std::numbers::pi * (index + 0.5) / count;
  scene::Light light;
  light.type = scene::LightType::Point;
  light.position = {7 * std::cos(angle), 4 * std::sin(angle), 8};
  light.color = glm::dvec3(120.0 / count);
  return light;
}

std::vector<SweepSpec> defineSweeps(const BenchOptions& options) {
  const bool quick = options.quick;
  const scene::Scene preview = scene::loadStatedScene(options.root / "scenes/examples/preview.json");
  // Refinement is normally chosen from the objects' size on screen, which
  // would change the geometry along with the resolution; pin it.
  auto pinned = [](scene::Scene scene, int isolation, int rate) {
    for (scene::Object& object : scene.objects) object.isolationLevel = isolation;
    scene.render.tessellationRate = rate;
    return scene;
  };
  auto sized = [](scene::Scene scene, int width, int height) {
    scene.render.width = width;
    scene.render.height = height;
    return scene;
  };
  const std::vector<SeriesSpec> allFour{{Backend::Gpu, scene::IntersectionMethod::Exact},
                                        {Backend::Gpu, scene::IntersectionMethod::Tessellated},
                                        {Backend::Cpu, scene::IntersectionMethod::Exact},
                                        {Backend::Cpu, scene::IntersectionMethod::Tessellated}};
  std::vector<SweepSpec> sweeps;

  auto sweepOf = [](std::string name, std::string title, std::string xLabel, scene::Scene base) {
    SweepSpec sweep;
    sweep.name = std::move(name);
    sweep.title = std::move(title);
    sweep.xLabel = std::move(xLabel);
    sweep.base = std::move(base);
    return sweep;
  };
  auto sizeOf = [](const scene::Scene& scene) {
    return std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height);
  };

  SweepSpec resolution =
      sweepOf("scaling_resolution", "Time against resolution (square images)", "pixels", pinned(preview, 3, 4));
  resolution.fixed = "preview scene, isolation 3, tessellated k = 4, its light and prefiltered environment";
  resolution.steps = quick ? std::vector<int>{16, 32} : std::vector<int>{32, 64, 128, 256, 512};
  resolution.xOf = [](int side) { return double(side) * side; };
  resolution.apply = [](scene::Scene& scene, int side) {
    scene.render.width = side;
    scene.render.height = side;
  };
  resolution.series = allFour;
  // The exact method costs several times the tessellated one per ray; past
  // 128² it alone would take the section's whole time budget.
  for (SeriesSpec& spec : resolution.series)
    if (spec.method == scene::IntersectionMethod::Exact && !quick) spec.steps = {32, 48, 64, 96, 128};
  sweeps.push_back(resolution);

  SweepSpec patches =
      sweepOf("scaling_patches", "Time against patch count (suzanne, isolation levels)", "patches",
              sized(scene::loadStatedScene(options.root / "scenes/cages/suzanne.obj"), quick ? 32 : 96, quick ? 32 : 96));
  patches.base.render.tessellationRate = 2;
  patches.fixed = "suzanne, " + sizeOf(patches.base) + ", tessellated k = 2, one directional light";
  patches.steps = quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 3, 4};
  patches.apply = [](scene::Scene& scene, int level) {
    for (scene::Object& object : scene.objects) object.isolationLevel = level;
  };
  patches.xIsPatches = true;
  patches.series = allFour;
  sweeps.push_back(patches);

  SweepSpec lights = sweepOf("scaling_lights", "Time against light count (point lights)", "point lights",
                             sized(pinned(preview, 3, 4), quick ? 32 : 64, quick ? 16 : 32));
  lights.base.environment.reset();
  lights.fixed = "preview scene, " + sizeOf(lights.base) + ", isolation 3, k = 4, no environment";
  lights.steps = quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4, 8, 16, 32};
  lights.apply = [](scene::Scene& scene, int count) {
    scene.lights.clear();
    for (int i = 0; i < count; ++i) scene.lights.push_back(pointLight(i, count));
  };
  lights.series = allFour;
  sweeps.push_back(lights);

  SweepSpec ibl = sweepOf("scaling_ibl", "Time against IBL samples (sampled, pairs per camera sample)",
                          "IBL sample pairs N", sized(pinned(preview, 3, 4), quick ? 32 : 48, quick ? 16 : 24));
  ibl.base.lights.clear();
  ibl.base.environment->method = scene::IblMethod::Sampled;
  ibl.fixed = "preview scene, " + sizeOf(ibl.base) + ", tessellated k = 4, no punctual lights";
  ibl.steps = quick ? std::vector<int>{1, 4} : std::vector<int>{1, 4, 16, 64, 256};
  ibl.apply = [](scene::Scene& scene, int samples) { scene.environment->samples = samples; };
  // The exact method only changes the visibility rays' cost, which the
  // light sweep already measures; here the occlusion is what matters.
  for (Backend backend : {Backend::Gpu, Backend::Cpu})
    for (bool occlusion : {false, true})
      ibl.series.push_back({backend, scene::IntersectionMethod::Tessellated,
                            occlusion ? "occlusion on" : "occlusion off",
                            [occlusion](scene::Scene& scene) { scene.environment->occlusion = occlusion; }});
  sweeps.push_back(ibl);
  return sweeps;
}

}  // namespace

void runScaling(Renderer& renderer, const BenchOptions& options, Report& report) {
  const fs::path directory = options.output / "scaling";
  fs::create_directories(directory);
  const std::vector<SweepSpec> sweeps = defineSweeps(options);
  std::vector<std::vector<Series>> results;
  std::vector<std::vector<std::string>> csv, table;
  for (const SweepSpec& sweep : sweeps) {
    results.push_back(runSweep(renderer, sweep, options));
    writeChart(directory, sweep, results.back());
    for (const Series& series : results.back()) {
      for (std::size_t i = 0; i < series.x.size(); ++i)
        csv.push_back({sweep.name, series.backend, series.method, series.variant, cell(series.x[i]),
                       cell(series.milliseconds[i])});
      table.push_back({sweep.xLabel, series.label(), exponentText(series.fit),
                       cell(series.fit.xFirst) + " … " + cell(series.fit.xLast), std::to_string(series.fit.points)});
    }
  }
  writeCsv(directory / "scaling.csv", {"sweep", "backend", "method", "variant", "x", "milliseconds"}, csv);

  report.heading("Scaling");
  report.paragraph(
      "Time of the trace and shade stages (GPU timestamps, CPU wall time; refinement, BVH and environment "
      "preparation excluded), median of " +
      std::to_string(options.repeats) +
      " runs after one untimed warm-up per series, against each swept quantity with the rest held fixed. "
      "Each series is fitted with t = a x^b by least squares on log-log axes over the upper half of its points "
      "(where the fixed per-image cost no longer dominates; all points when there are only two); ± is the "
      "standard error of b. Data: [scaling.csv](scaling/scaling.csv).");
  for (std::size_t w = 0; w < sweeps.size(); ++w)
    report.image("scaling/" + sweeps[w].name + ".svg", sweeps[w].title + ": " + sweeps[w].fixed);
  report.table({"against", "series", "exponent b", "fitted over x", "points fitted"}, table);
  report.paragraph(describe(sweeps, results));
}

}  // namespace facet::analysis::bench

#include "analysis/ibl_chart.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "analysis/antialiasing_slope.h"
#include "analysis/gnuplot.h"
#include "analysis/image_compare.h"
#include "analysis/report.h"
#include "analysis/timing.h"
#include "engine/image/image_io.h"
#include "scenes/scene_file.h"

namespace facet::analysis {
namespace {

namespace fs = std::filesystem;

struct ChartPoint {
  std::string setup;
  double alpha = 0;
  scene::IblMethod method = scene::IblMethod::Sampled;
  int samples = 0;
  double milliseconds = 0;
  double prepMilliseconds = 0;
  double relativeRmse = 0;
  double maxAbsError = 0;
};

const char* methodName(scene::IblMethod method) {
  switch (method) {
    case scene::IblMethod::Sampled:
      return "sampled";
    case scene::IblMethod::Prefiltered:
      return "prefiltered";
    case scene::IblMethod::Filtered:
      return "filtered";
  }
  return "";
}

// The methods with N, in the chart's order; the split sum has none.
constexpr scene::IblMethod kMethodsWithSamples[] = {scene::IblMethod::Sampled, scene::IblMethod::Filtered};

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
  writePng(path, pair, middleGreyExposure(reference));
}

// The camera samples' curve: printed, and antialiasing.csv.
void writeAntialiasing(Renderer& renderer, const scene::Scene& scene, const IblChartSettings& settings) {
  const AntialiasingCurve curve = measureAntialiasing(renderer, scene, settings.antialiasingSamples, settings.backend);
  std::printf("camera samples, prefiltered, against %d spp: relative RMSE on silhouette / smooth pixels\n",
              curve.referenceSamples);
  std::vector<std::vector<std::string>> rows;
  for (const AntialiasingPoint& p : curve.points) {
    std::printf("  %4d spp  %.3g  %.3g\n", p.samplesPerPixel, p.silhouetteRmse, p.smoothRmse);
    rows.push_back({std::to_string(p.samplesPerPixel), formatNumber(p.silhouetteRmse), formatNumber(p.smoothRmse)});
  }
  if (!std::isnan(curve.silhouetteSlope))
    std::printf("  error slope over spp >= 4: silhouette %.2f, smooth %.2f\n", curve.silhouetteSlope,
                curve.smoothSlope);
  writeCsv(settings.output / "antialiasing.csv",
           {"samples_per_pixel", "silhouette_relative_rmse", "smooth_relative_rmse"}, rows);
}

void writePointsCsv(const fs::path& path, const std::vector<ChartPoint>& points) {
  std::vector<std::vector<std::string>> rows;
  for (const ChartPoint& p : points)
    rows.push_back({p.setup, formatNumber(p.alpha), methodName(p.method),
                    p.method == scene::IblMethod::Prefiltered ? "" : std::to_string(p.samples),
                    formatNumber(p.milliseconds), formatNumber(p.prepMilliseconds), formatNumber(p.relativeRmse),
                    formatNumber(p.maxAbsError)});
  writeCsv(
      path,
      {"setup", "alpha", "method", "samples", "milliseconds", "prep_milliseconds", "relative_rmse", "max_abs_error"},
      rows);
}

// The log-log slope of error against N over a curve's points with N >= 16,
// where the pixel's own strata have begun to resolve: -0.5 for independent
// samples, steeper for stratified ones. NaN with fewer than two points.
double errorSlope(const std::vector<ChartPoint>& points, const std::string& setup, double alpha,
                  scene::IblMethod method) {
  std::vector<std::pair<double, double>> xy;
  for (const ChartPoint& p : points)
    if (p.setup == setup && p.alpha == alpha && p.method == method && p.samples >= 16)
      xy.emplace_back(std::log(double(p.samples)), std::log(p.relativeRmse));
  if (xy.size() < 2) return NAN;
  double mx = 0, my = 0;
  for (const auto& [x, y] : xy) mx += x / double(xy.size()), my += y / double(xy.size());
  double sxy = 0, sxx = 0;
  for (const auto& [x, y] : xy) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
  return sxy / sxx;
}

std::string slopeLabel(double slope) {
  return std::isnan(slope) ? "" : ", slope " + formatNumber(std::round(slope * 100) / 100);
}

// One panel per setup; per alpha a colour, sampled as a solid line through
// its N points (N written beside the first alpha's), filtered as a dashed
// one, the split sum as one large marker of the same colour.
void writeChart(const fs::path& directory, const std::vector<std::string>& setups, const std::vector<double>& alphas,
                const std::vector<ChartPoint>& points, const std::string& subtitle) {
  std::ostringstream data, script;
  for (const std::string& setup : setups)
    for (double alpha : alphas)
      for (scene::IblMethod method :
           {scene::IblMethod::Sampled, scene::IblMethod::Filtered, scene::IblMethod::Prefiltered}) {
        for (const ChartPoint& p : points)
          if (p.setup == setup && p.alpha == alpha && p.method == method)
            data << p.milliseconds << " " << p.relativeRmse << " " << p.samples << "\n";
        data << "\n\n";
      }
  static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  script << "set output OUTPUT\n"
         << "set multiplot layout 1," << setups.size()
         << " title \"IBL error against time: sampled (solid, N pairs), filtered (dashed, N pairs) "
         << "and the prefiltered split sum (squares)\\n"
         << subtitle << "\" noenhanced\n"
         << "set logscale xy\nset grid\nset format y '10^{%L}'\nset key bottom left box opaque font ',10'\n"
         << "set xlabel 'time per image (ms, GPU stages)'\nset ylabel 'relative RMSE vs reference'\n";
  std::size_t block = 0;
  for (const std::string& setup : setups) {
    script << "set title \"" << setup << "\" noenhanced\nplot ";
    for (std::size_t a = 0; a < alphas.size(); ++a, block += 3) {
      const char* colour = kColours[a % std::size(kColours)];
      const std::string label = formatNumber(alphas[a]);
      script << (a ? ", " : "") << "DATA index " << block << " using 1:2 with linespoints lw 2 pt 7 ps 0.8 lc rgb '"
             << colour << "' title 'sampled, alpha " << label
             << slopeLabel(errorSlope(points, setup, alphas[a], scene::IblMethod::Sampled)) << "', DATA index "
             << block + 1 << " using 1:2 with linespoints lw 2 dt 2 pt 9 ps 0.8 lc rgb '" << colour
             << "' title 'filtered, alpha " << label
             << slopeLabel(errorSlope(points, setup, alphas[a], scene::IblMethod::Filtered)) << "', DATA index "
             << block + 2 << " using 1:2 with points pt 5 ps 2 lc rgb '" << colour << "' title 'prefiltered, alpha "
             << label << "'";
      if (a == 0)
        for (std::size_t curve : {block, block + 1})
          script << ", DATA index " << curve
                 << " using 1:2:(sprintf('N=%d', $3)) with labels offset char 0,1 font ',8' notitle";
    }
    script << "\n";
  }
  script << "unset multiplot\n";
  const int width = 620 * int(setups.size()), height = 560;
  runGnuplot(script.str(), data.str(), directory / "ibl_chart.svg", width, height);
  runGnuplot(script.str(), data.str(), directory / "ibl_chart.png", width, height);
}

}  // namespace

void writeIblChart(Renderer& renderer, const IblChartSettings& settings) {
  if (settings.sampleCounts.empty() || settings.alphas.empty() || settings.environments.empty())
    throw std::invalid_argument("ibl-chart: needs sample counts, alphas and environments");
  const int referenceSamples = kIblReferenceFactor * settings.sampleCounts.back();
  const Backend backend = settings.backend;
  const fs::path& output = settings.output;
  scene::Scene base = settings.base;
  // The chart measures the environment term alone.
  base.lights.clear();
  if (!base.environment) base.environment.emplace();
  // The split sum has no visibility: without occlusion both methods
  // integrate the same unshadowed term, and the chart isolates the
  // integration error.
  base.environment->occlusion = false;
  fs::create_directories(output);

  std::vector<std::string> setups;
  std::vector<ChartPoint> points;
  for (const fs::path& file : settings.environments) {
    scene::Scene scene = base;
    scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(file));
    const std::string setup = file.stem().string();
    setups.push_back(setup);
    for (double alpha : settings.alphas) {
      for (materials::Material& material : scene.materials) material.alpha = alpha;
      auto renderWith = [&](scene::IblMethod method, int samples, Backend on) {
        scene.environment->method = method;
        scene.environment->samples = samples;
        return renderer.render(scene, on);
      };
      // Its own random numbers: sharing the estimates' would under-report their error.
      scene.environment->seed = 1;
      const RenderReport reference = renderWith(scene::IblMethod::Sampled, referenceSamples, backend);
      scene.environment->seed = 0;
      // Untimed first runs: they compile each method's kernels and warm the
      // prefilter's disk cache.
      renderWith(scene::IblMethod::Sampled, 1, backend);
      renderWith(scene::IblMethod::Filtered, 1, backend);
      const RenderReport firstPrefiltered = renderWith(scene::IblMethod::Prefiltered, 1, backend);
      std::printf("%s, alpha %g: reference N=%d %.0f ms; first prefiltered run: preparation %.1f ms\n", setup.c_str(),
                  alpha, referenceSamples, traceMilliseconds(reference), preparationMilliseconds(firstPrefiltered));

      auto measure = [&](scene::IblMethod method, int samples) {
        std::vector<double> times, preparations;
        Image image;
        for (int r = 0; r < settings.repeats; ++r) {
          RenderReport report = renderWith(method, samples, backend);
          times.push_back(traceMilliseconds(report));
          preparations.push_back(preparationMilliseconds(report));
          if (r == 0) image = std::move(report.image);
        }
        const ImageError error = compareToReference(image, reference.image);
        if (error.compared == 0) throw std::runtime_error("ibl-chart: the reference image covers no pixel");
        ChartPoint p{
            setup, alpha, method, samples, median(times), median(preparations), error.relativeRmse, error.maxAbsolute};
        const std::string name = method == scene::IblMethod::Prefiltered
                                     ? std::string("prefiltered")
                                     : methodName(method) + (" N=" + std::to_string(samples));
        std::printf("  %-18s %9.1f ms  (+%.1f ms preparation)  relative RMSE %.3g  max |error| %.3g\n", name.c_str(),
                    p.milliseconds, p.prepMilliseconds, p.relativeRmse, p.maxAbsError);
        std::fflush(stdout);
        points.push_back(p);
        return image;
      };
      for (scene::IblMethod method : kMethodsWithSamples)
        for (int samples : settings.sampleCounts)
          if (method == scene::IblMethod::Sampled || samples <= kMaxFilteredChartSamples) measure(method, samples);
      const Image prefiltered = measure(scene::IblMethod::Prefiltered, 1);
      for (scene::IblMethod method : kMethodsWithSamples) {
        // A slope needs two sample counts of 16 or more (--quick has one).
        const double slope = errorSlope(points, setup, alpha, method);
        if (!std::isnan(slope)) std::printf("  %s: error slope over N >= 16: %.2f\n", methodName(method), slope);
      }
      writeComparison(output / (setup + "_alpha" + formatNumber(alpha) + ".png"), reference.image, prefiltered);
    }
  }
  if (!settings.antialiasingSamples.empty()) {
    scene::Scene scene = base;
    scene.environment->map =
        std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(settings.environments.front()));
    writeAntialiasing(renderer, scene, settings);
  }
  writePointsCsv(output / "ibl_chart.csv", points);
  const std::string subtitle = std::to_string(base.render.width) + "x" + std::to_string(base.render.height) + ", " +
                               toString(backend) + ", reference: sampled N=" + std::to_string(referenceSamples) +
                               ", occlusion off, no punctual lights";
  writeChart(output, setups, settings.alphas, points, subtitle);
}

}  // namespace facet::analysis

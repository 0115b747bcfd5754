// facet bench, section "cycles": Blender Cycles beside facet on the material
// preview (the gold cube, Catmull-Clark, lit by the courtyard alone), both
// against one converged facet reference: Cycles' error and render time per
// sample count, facet's curves, and facet's time to Cycles' error. Blender
// is optional: without it the section prints a note and is skipped.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/bench/cycles_sections.h"
#include "analysis/gnuplot.h"
#include "engine/image/exr_file.h"
#include "engine/image/image_io.h"
#include "rules/rules.h"
#include "scenes/light_transport.h"
#include "scenes/scene_file.h"

namespace facet::analysis::bench {
namespace {

namespace fs = std::filesystem;

// One facet method at a number of camera samples per pixel, over pairs per
// camera sample (the split sum has one).
struct FacetCurve {
  scene::IblMethod method = scene::IblMethod::Sampled;
  int cameraSamples = 1;
  std::vector<int> pairs;
};

struct CyclesSizes {
  int size;
  std::vector<int> cyclesSamples;
  int cyclesTarget;  // the sample count whose error facet is asked to reach
  std::vector<FacetCurve> curves;
  int referenceCameraSamples, referencePairs;
};

CyclesSizes cyclesSizesFor(bool quick) {
  using scene::IblMethod;
  if (quick) return {32, {1, 4}, 4, {{IblMethod::Sampled, 1, {1, 4}}, {IblMethod::Filtered, 1, {4}}}, 4, 16};
  return {512,
          {4, 16, 64, 256},
          64,
          {{IblMethod::Sampled, 1, {1, 4, 16, 64, 256}},
           {IblMethod::Sampled, 4, {1, 4, 16, 64}},
           {IblMethod::Sampled, 16, {1, 4, 16}},
           {IblMethod::Filtered, 1, {4, 16, 64}},
           {IblMethod::Filtered, 4, {4, 16, 64}},
           {IblMethod::Prefiltered, 4, {1}}},
          64,
          64};
}

std::string curveName(const FacetCurve& c) {
  const char* method = c.method == scene::IblMethod::Sampled    ? "sampled"
                       : c.method == scene::IblMethod::Filtered ? "filtered"
                                                                : "prefiltered";
  return method + (", " + std::to_string(c.cameraSamples) + " spp");
}

// Every curve as a line through its points, N written beside each; the
// error facet is asked to reach as a dotted level.
void writeChart(const fs::path& path, const std::vector<std::vector<Point>>& curves, double targetError,
                const std::string& subtitle) {
  std::ostringstream data, script;
  for (const std::vector<Point>& curve : curves) {
    for (const Point& p : curve) data << p.milliseconds << " " << p.relativeRmse << " " << p.samples << "\n";
    data << "\n\n";
  }
  script << "set output OUTPUT\n"
         << "set title \"Material preview: Cycles (N spp) and facet (N pairs per camera sample)\\n"
         << subtitle << "\" noenhanced\n"
         << "set logscale xy\nset grid\nset key outside right top box font ',10'\n"
         << "set xlabel 'time per image (ms; facet: GPU tracing stages, Cycles: render call)'\n"
         << "set ylabel 'relative RMSE vs facet reference'\n"
         << "plot " << targetError << " with lines dt 3 lc rgb 'black' title 'Cycles error to reach'";
  // Cycles (the first curve) in black, facet's in distinct colours.
  static constexpr const char* kColours[] = {"#000000", "#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                             "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  for (std::size_t i = 0; i < curves.size(); ++i)
    script << ", DATA index " << i << " using 1:2 with linespoints lw " << (i == 0 ? 3 : 1.5) << " pt 7 lc rgb '"
           << kColours[i % std::size(kColours)] << "' title '" << curves[i].front().curve << "', DATA index " << i
           << " using 1:2:(sprintf('%d', $3)) with labels offset char 0.8,0.6 font ',7' tc rgb '"
           << kColours[i % std::size(kColours)] << "' notitle";
  script << "\n";
  runGnuplot(script.str(), data.str(), path, 960, 600);
}

// The gold cube, Catmull-Clark, under the courtyard alone, in the models
// Cycles' plain GGX Principled metallic has: separable Smith G and its
// metallic Fresnel (docs/shading.md).
scene::Scene materialPreview(const fs::path& root, const fs::path& map, int size) {
  scene::Scene scene = scene::loadStatedScene(root / "scenes/examples/gold_cube.gltf");
  scene::overrideSubdivision(scene, "catmull-clark", "cycles");
  scene.lights.clear();
  scene.environment.emplace();
  scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(map));
  scene.environment->rotationDegrees = peers::kCyclesMapRotationDegrees;
  // A convex surface never shadows itself: occlusion changes nothing but the time.
  scene.environment->occlusion = false;
  scene.render.width = scene.render.height = size;
  scene.render.method = scene::IntersectionMethod::Exact;
  for (materials::Material& m : scene.materials) {
    m.geometry = rules::f64::G_SMITH_GGX;
    m.fresnel = rules::f64::F_BLENDER_METALLIC;
  }
  return scene;
}

RenderReport renderPreview(Renderer& renderer, scene::Scene scene, scene::IblMethod method, int cameraSamples,
                           int pairs, std::uint32_t seed) {
  scene.render.samplesPerPixel = cameraSamples;
  scene.environment->method = method;
  scene.environment->samples = pairs;
  scene.environment->seed = seed;
  return renderer.render(scene, Backend::Gpu);
}

// Cycles' points, from the images and times the script wrote; `converged`
// gets the image of the largest sample count.
std::vector<Point> cyclesPoints(const fs::path& directory, const CyclesSizes& sizes, const Image& reference,
                                Image& converged) {
  const std::map<int, double> seconds = peers::readCyclesTimes(directory / "cycles_times.csv", sizes.cyclesSamples);
  std::vector<Point> points;
  for (int samples : sizes.cyclesSamples) {
    converged = peers::readCyclesImage(directory / ("cycles_" + std::to_string(samples) + "spp.exr"), reference);
    points.push_back(
        {"Cycles", samples, 1000 * seconds.at(samples), compareToReference(converged, reference).relativeRmse});
    std::printf("  cycles %4d spp          %9.1f ms  relative RMSE %.3g\n", samples, points.back().milliseconds,
                points.back().relativeRmse);
  }
  return points;
}

// facet's curves, each point the median time of `repeats` after an untimed run per curve.
std::vector<std::vector<Point>> facetCurves(Renderer& renderer, const scene::Scene& scene, const CyclesSizes& sizes,
                                            int repeats, const Image& reference) {
  for (const FacetCurve& c : sizes.curves)
    renderPreview(renderer, scene, c.method, c.cameraSamples, c.pairs.front(), 0);
  std::vector<std::vector<Point>> curves;
  for (const FacetCurve& c : sizes.curves) {
    std::vector<Point>& curve = curves.emplace_back();
    for (int pairs : c.pairs)
      curve.push_back(timedPoint(
          curveName(c), pairs, repeats,
          [&] { return renderPreview(renderer, scene, c.method, c.cameraSamples, pairs, 0); }, reference));
  }
  return curves;
}

}  // namespace

void runCycles(Renderer& renderer, const BenchOptions& options, Report& report) {
  report.heading("Cycles: the material preview");
  const std::optional<peers::CyclesPeer> peer = findCyclesPeer(options.root, "cycles", report);
  if (!peer) return;
  const CyclesSizes sizes = cyclesSizesFor(options.quick);
  const fs::path directory = options.output / "cycles";
  fs::create_directories(directory);
  const fs::path map = options.root / "scenes/environments/courtyard_256x128.hdr";
  const scene::Scene scene = materialPreview(options.root, map, sizes.size);

  // Its own random numbers: sharing the estimates' would under-report their error.
  const Image reference =
      renderPreview(renderer, scene, scene::IblMethod::Sampled, sizes.referenceCameraSamples, sizes.referencePairs, 1)
          .image;
  writeExr(directory / "facet_reference.exr", reference);

  const unsigned threads = peers::cyclesThreads();
  std::printf("cycles: rendering with %s on %u threads\n", peer->blender.c_str(), threads);
  std::fflush(stdout);
  peers::renderInCycles(peer->blender, peer->script, peers::describeForCycles(scene, directory),
                        {sizes.cyclesSamples, options.repeats, 0}, directory);
  Image cyclesConverged;
  const std::vector<Point> cycles = cyclesPoints(directory, sizes, reference, cyclesConverged);
  const std::vector<std::vector<Point>> curves = facetCurves(renderer, scene, sizes, options.repeats, reference);

  std::vector<std::vector<Point>> charted{cycles};
  charted.insert(charted.end(), curves.begin(), curves.end());
  std::vector<std::vector<std::string>> csv;
  for (const std::vector<Point>& curve : charted)
    for (const Point& p : curve)
      csv.push_back({p.curve, std::to_string(p.samples), cell(p.milliseconds), cell(p.relativeRmse)});
  writeCsv(directory / "cycles.csv", {"renderer", "samples", "milliseconds", "relative_rmse"}, csv);

  // The converged images first: a mismatch of orientation or units shows
  // here, before any time is compared.
  const glm::dvec3 facetMean = coveredMean(reference, reference), cyclesMean = coveredMean(cyclesConverged, reference);
  std::vector<std::vector<std::string>> agreement;
  for (int c = 0; c < 3; ++c)
    agreement.push_back({std::string(1, "RGB"[c]), formatted("%.4f", facetMean[c]), formatted("%.4f", cyclesMean[c]),
                         formatted("%+.2f%%", 100 * (cyclesMean[c] / facetMean[c] - 1))});
  std::printf("  mean covered radiance, Cycles %d spp / facet reference - 1: R %+.4f G %+.4f B %+.4f\n",
              sizes.cyclesSamples.back(), cyclesMean.r / facetMean.r - 1, cyclesMean.g / facetMean.g - 1,
              cyclesMean.b / facetMean.b - 1);
  const Point& target =
      *std::find_if(cycles.begin(), cycles.end(), [&](const Point& p) { return p.samples == sizes.cyclesTarget; });
  const std::string sentence = verdict(curves, target);
  std::printf("  %s\n", sentence.c_str());

  report.paragraph(
      "The gold cube (scenes/examples/gold_cube.gltf, Catmull-Clark) under " + map.filename().string() + " alone, " +
      std::to_string(sizes.size) + "², Blender's metallic Fresnel, separable Smith G, occlusion off. Cycles (" +
      peer->blender.string() + ", " + std::to_string(threads) +
      " threads, tools/blender/cycles_scene.py): the cage subdivided " +
      std::to_string(peers::kCyclesSubdivisionLevels) +
      " levels with its vertices on the limit surface, 1 px box filter, no clamping, no denoiser; its time is the "
      "median render call. facet: GPU backend, its tracing stages' time. Error: relative RMSE against facet sampled "
      "with " +
      std::to_string(sizes.referenceCameraSamples) + " camera samples x " + std::to_string(sizes.referencePairs) +
      " pairs (seed 1), over the pixels it covers. CSV: cycles/cycles.csv.");
  report.table({"channel", "facet reference mean", "Cycles " + std::to_string(sizes.cyclesSamples.back()) + " spp mean",
                "Cycles / facet"},
               agreement);
  std::vector<std::vector<std::string>> table;
  for (const std::vector<Point>& curve : charted)
    for (const Point& p : curve)
      table.push_back(
          {p.curve == "Cycles" ? p.curve : "facet " + p.curve,
           (p.curve == "Cycles" ? "" : "N = ") + std::to_string(p.samples) + (p.curve == "Cycles" ? " spp" : ""),
           formatted("%.1f", p.milliseconds), formatted("%.3g", p.relativeRmse)});
  report.table({"renderer", "samples", "ms", "relative RMSE"}, table);
  for (const char* chart : {"cycles.svg", "cycles.png"})
    writeChart(directory / chart, charted, target.relativeRmse,
               std::to_string(sizes.size) + "², " + std::to_string(threads) + " threads");
  report.image("cycles/cycles.svg", "Cycles and facet: time against error on the material preview");
  report.paragraph(sentence + ".");
}

}  // namespace facet::analysis::bench

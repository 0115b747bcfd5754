// facet bench, section "pareto": per scene, every method and knob against a
// converged reference, time against error on a log-log chart with the
// non-dominated points joined, Embree 3's tessellation rates beside facet's
// methods on the torture cages.
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/gnuplot.h"
#include "analysis/pareto.h"
#include "engine/image/image_io.h"
#include "scenes/scene_file.h"

#if FACET_HAVE_EMBREE
#include "analysis/peers/embree_peer.h"
#endif

namespace facet::analysis::bench {
namespace {

namespace fs = std::filesystem;

// What the chart's y axis measures: rendered radiance, or where the rays
// hit (the torture cages, where Embree, which only casts, joins in).
enum class ErrorAxis { Beauty, Depth };

// One knob setting of one method. `knob` is empty for the prefiltered split
// sum, which has none.
struct Setting {
  std::string method;  // exact, tessellated, sampled, prefiltered
  std::string knob;    // epsilon, k, N, rate
  double value = 0;

  std::string label() const {
    if (knob.empty()) return method;
    const std::string shown = knob == "epsilon" ? "ε" : knob;
    return method + " " + shown + "=" + cell(value);
  }
};

struct Point {
  std::string backend;  // gpu, cpu, embree
  Setting setting;
  double milliseconds = 0;
  ImageError error;
  Image image;  // empty for Embree, which returns depth alone
};

struct Scenario {
  std::string name;
  std::string description;
  scene::Scene scene;
  ErrorAxis axis = ErrorAxis::Beauty;
  std::vector<Setting> settings;
  bool embreePeer = false;
  int referenceSamples = 0;  // sampled IBL pairs of the reference; 0: the scene's own environment method
};

// Chosen so the default run stays within its share of `facet bench`'s time
// on 2 lavapipe cores.
struct Sizes {
  int previewWidth, previewHeight;
  int cageSize;
  int iblWidth, iblHeight;
  std::vector<std::string> cages;
  std::vector<double> tolerances;
  std::vector<int> tessellationRates;
  std::vector<int> iblSamples;
  int referenceSamples;
  std::vector<int> embreeRates;
};

Sizes sizesFor(bool quick) {
  if (quick) return {48, 24, 32, 48, 24, {"pole24"}, {1e-4}, {2, 4}, {1, 4}, 64, {1, 4, 16}};
  return {192,
          96,
          96,
          48,
          24,
          {"pole24", "valence_3_to_10", "creased_box"},
          {1e-3, 1e-4, 1e-5, 1e-6},
          {1, 2, 4, 8, 16},
          {1, 4, 16, 64, 256},
          1024,
          {1, 2, 4, 8, 16, 32, 64}};
}

// The y value of the chart: relative RMSE of the beauty, or mean relative
// depth error (the maximum is set by single silhouette pixels).
double chartedError(const ImageError& e, ErrorAxis axis) {
  return axis == ErrorAxis::Beauty ? e.relativeRmse : e.depthRelativeMean;
}

std::string axisName(ErrorAxis axis) {
  return axis == ErrorAxis::Beauty ? "beauty relative RMSE" : "mean relative depth error";
}

// A point is good enough below this error; the report shows the fastest such
// render. Depth is held to a tighter bar: 1% of the depth is far more than a
// pixel's worth of surface on these cages.
double goodEnough(ErrorAxis axis) { return axis == ErrorAxis::Beauty ? 0.01 : 1e-4; }

// Log axes cannot show 0: such errors are drawn here (said on the chart).
constexpr double kChartFloor = 1e-12;

void apply(const Setting& s, scene::Scene& scene) {
  if (s.method == "exact") {
    scene.render.method = scene::IntersectionMethod::Exact;
    scene.render.exactTolerance = s.value;
  } else if (s.method == "tessellated") {
    scene.render.method = scene::IntersectionMethod::Tessellated;
    scene.render.tessellationRate = int(s.value);
  } else if (s.method == "sampled") {
    scene.environment->method = scene::IblMethod::Sampled;
    scene.environment->samples = int(s.value);
  } else if (s.method == "prefiltered") {
    scene.environment->method = scene::IblMethod::Prefiltered;
  }
}

// The smallest ε the GPU honours, as a fraction of the scene's diagonal:
// 2^-20 (8 float ulps) of the largest coordinate of the scene and the eye
// (docs/rendering.md, "The GPU path").
double gpuToleranceFloor(const scene::Scene& scene) {
  const scene::Aabb bounds = scene::cageBounds(scene);
  double largest = 0;
  for (const glm::dvec3& p : {bounds.lo, bounds.hi, scene.camera.eye})
    for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(p[i]));
  return std::ldexp(largest, -20) / glm::length(bounds.hi - bounds.lo);
}

std::vector<Setting> geometrySettings(const Sizes& sizes) {
  std::vector<Setting> settings;
  for (double epsilon : sizes.tolerances) settings.push_back({"exact", "epsilon", epsilon});
  for (int k : sizes.tessellationRates) settings.push_back({"tessellated", "k", double(k)});
  return settings;
}

std::vector<Scenario> scenarios(const BenchOptions& options, const Sizes& sizes) {
  std::vector<Scenario> list;
  const scene::Scene preview = scene::loadScene(options.root / "scenes/examples/preview.json");

  Scenario defaultPreview{"preview", "", preview, ErrorAxis::Beauty, geometrySettings(sizes)};
  defaultPreview.scene.render.width = sizes.previewWidth;
  defaultPreview.scene.render.height = sizes.previewHeight;
  defaultPreview.description = "the default preview (scenes/examples/preview.json: key light, courtyard prefiltered)";
  list.push_back(defaultPreview);

  for (const std::string& cage : sizes.cages) {
    Scenario torture{cage, "", scene::loadScene(options.root / ("scenes/cages/" + cage + ".obj")), ErrorAxis::Depth,
                     geometrySettings(sizes)};
    torture.scene.render.width = torture.scene.render.height = sizes.cageSize;
    torture.description = "torture cage scenes/cages/" + cage + ".obj, default framing and key light";
    torture.embreePeer = true;
    list.push_back(torture);
  }

  // The environment alone, sampled with shadow rays against the split sum:
  // the sun makes the sampled method's variance and the split sum's missing
  // occlusion both show. The geometry is tessellated at a fixed k so that
  // the points differ in lighting alone and N = 256 stays affordable.
  Scenario ibl{"ibl_sunrise", "", preview, ErrorAxis::Beauty, {}};
  ibl.scene.render.width = sizes.iblWidth;
  ibl.scene.render.height = sizes.iblHeight;
  ibl.scene.lights.clear();
  ibl.scene.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(options.root / "scenes/environments/sunrise.exr"));
  ibl.scene.environment->occlusion = true;
  ibl.scene.render.method = scene::IntersectionMethod::Tessellated;
  ibl.scene.render.tessellationRate = 8;
  for (int n : sizes.iblSamples) ibl.settings.push_back({"sampled", "N", double(n)});
  ibl.settings.push_back({"prefiltered", "", 0});
  ibl.referenceSamples = sizes.referenceSamples;
  ibl.description =
      "the preview's geometry lit by scenes/environments/sunrise.exr alone (bright sun), occlusion on, "
      "tessellated k=8";
  list.push_back(ibl);
  return list;
}

// CPU, exact at the default ε (1e-9 of each object's diagonal), same size and
// samples per pixel; sampled IBL with many pairs where the scene's lighting is
// the knob.
RenderReport renderReference(Renderer& renderer, const Scenario& s) {
  scene::Scene reference = s.scene;
  reference.render.method = scene::IntersectionMethod::Exact;
  reference.render.exactTolerance.reset();
  if (s.referenceSamples > 0) {
    reference.environment->method = scene::IblMethod::Sampled;
    reference.environment->samples = s.referenceSamples;
  }
  return renderer.render(reference, Backend::Cpu);
}

Point measure(Renderer& renderer, const Scenario& s, const Setting& setting, Backend backend, const Image& reference,
              const BenchOptions& options) {
  scene::Scene scene = s.scene;
  apply(setting, scene);
  // Untimed: compiles the GPU pipeline variant and fills the environment's
  // caches; its image is the one compared.
  RenderReport first = renderer.render(scene, backend);
  Point p{backend == Backend::Gpu ? "gpu" : "cpu", setting, 0, compareToReference(first.image, reference),
          std::move(first.image)};
  p.milliseconds = medianMilliseconds(options.repeats,
                                      [&] { return traceMilliseconds(renderer.render(scene, backend)); });
  return p;
}

#if FACET_HAVE_EMBREE
// Embree answers depth alone: its candidate image carries its coverage and
// depth and the reference's normals, so only depth, holes and extra pixels
// differ.
struct EmbreeRun {
  std::vector<Point> points;
  std::string notes;  // where Embree's surface departs from facet's
};

EmbreeRun measureEmbree(const Scenario& s, const Sizes& sizes, const Image& reference, const BenchOptions& options) {
  constexpr int kThreads = 2;  // the machine's cores, as lavapipe and the CPU reference use
  peers::EmbreeSubdivision embree(s.scene.objects.front().cage, kThreads);
  const int width = s.scene.render.width, height = s.scene.render.height;
  EmbreeRun run{{}, embree.notes()};
  for (int rate : sizes.embreeRates) {
    embree.setTessellationRate(rate);
    std::vector<float> depth;
    embree.castPrimary(s.scene.camera, width, height, depth);
    Image candidate(width, height);
    for (std::size_t i = 0; i < depth.size(); ++i) {
      candidate.shadingNormal[i] = reference.shadingNormal[i];
      if (!covered(depth[i])) continue;
      candidate.depth[i] = depth[i];
      candidate.beauty[i].a = 1;
      candidate.patchId[i] = 0;  // a hit: Embree names no facet patch
    }
    Point p{"embree", {"tessellated", "rate", double(rate)}, 0, compareToReference(candidate, reference), {}};
    p.milliseconds =
        medianMilliseconds(options.repeats, [&] { return embree.castPrimary(s.scene.camera, width, height, depth); });
    run.points.push_back(std::move(p));
  }
  return run;
}
#endif

std::vector<const Point*> paretoFrontier(const std::vector<Point>& points, ErrorAxis axis) {
  std::vector<Cost> costs;
  for (const Point& p : points) costs.push_back({p.milliseconds, chartedError(p.error, axis)});
  std::vector<const Point*> frontier;
  for (std::size_t i : paretoFront(costs)) frontier.push_back(&points[i]);
  return frontier;
}

std::string series(const Point& p) { return p.backend + " " + p.setting.method; }

// Three significant digits, for prose and tables (the CSV keeps every digit).
std::string threeDigits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string optionalCell(double value) { return std::isfinite(value) ? cell(value) : ""; }

void writePointsCsv(const fs::path& path, const std::string& sceneName, const std::vector<Point>& points) {
  std::vector<std::vector<std::string>> rows;
  for (const Point& p : points) {
    const bool hasNormals = p.backend != "embree";
    rows.push_back({sceneName, p.backend, p.setting.method, p.setting.knob,
                    p.setting.knob.empty() ? "" : cell(p.setting.value), cell(p.milliseconds),
                    hasNormals ? cell(p.error.relativeRmse) : "", hasNormals ? cell(p.error.maxAbsolute) : "",
                    cell(p.error.depthRelativeMax), cell(p.error.depthRelativeMean),
                    hasNormals ? optionalCell(p.error.normalRadiansMax) : "",
                    hasNormals ? optionalCell(p.error.normalRadiansMean) : "", std::to_string(p.error.holes),
                    std::to_string(p.error.extra), std::to_string(p.error.nonFinite)});
  }
  writeCsv(path,
           {"scene", "backend", "method", "knob", "value", "ms", "relative_rmse", "max_abs", "depth_rel_max",
            "depth_rel_mean", "normal_rad_max", "normal_rad_mean", "holes", "extra", "non_finite"},
           rows);
}

// One colour and marker per backend and method; the frontier as a dashed
// black line under them; each point labelled with its knob.
void writeChart(const fs::path& directory, const Scenario& s, const std::vector<Point>& points,
                const std::vector<const Point*>& frontier, const std::string& subtitle) {
  std::vector<std::string> names;
  for (const Point& p : points)
    if (std::find(names.begin(), names.end(), series(p)) == names.end()) names.push_back(series(p));
  auto charted = [&](const Point& p) { return std::max(chartedError(p.error, s.axis), kChartFloor); };
  std::ostringstream data, script;
  for (const Point* p : frontier) data << p->milliseconds << " " << charted(*p) << "\n";
  data << "\n\n";
  for (const std::string& name : names) {
    for (const Point& p : points)
      if (series(p) == name)
        data << p.milliseconds << " " << charted(p) << " \""
             << (p.setting.knob.empty()
                     ? ""
                     : (p.setting.knob == "epsilon" ? "ε" : p.setting.knob) + "=" + cell(p.setting.value))
             << "\"\n";
    data << "\n\n";
  }
  static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                             "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  static constexpr int kMarkers[] = {7, 5, 9, 11, 13, 15, 6, 4};
  script << "set output OUTPUT\n"
         << "set title \"" << s.name << ": time against " << axisName(s.axis) << "\\n"
         << subtitle << "\" noenhanced\n"
         << "set logscale xy\nset grid\nset format y '10^{%L}'\nset key outside right top box font ',10'\n"
         << "set xlabel 'time per image (ms; GPU: GPU timestamps of the tracing stages)'\n"
         << "set ylabel '" << axisName(s.axis) << " vs reference'\n"
         << "plot DATA index 0 using 1:2 with lines dt 2 lw 1.5 lc rgb 'black' title 'Pareto frontier'";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const char* colour = kColours[i % std::size(kColours)];
    script << ", DATA index " << i + 1 << " using 1:2 with points pt " << kMarkers[i % std::size(kMarkers)]
           << " ps 1.3 lc rgb '" << colour << "' title '" << names[i] << "', DATA index " << i + 1
           << " using 1:2:3 with labels offset char 0.6,0.6 left font ',7' tc rgb '" << colour << "' notitle";
  }
  script << "\n";
  runGnuplot(script.str(), data.str(), directory / ("pareto_" + s.name + ".svg"), 960, 600);
  runGnuplot(script.str(), data.str(), directory / ("pareto_" + s.name + ".png"), 960, 600);
}

std::string describe(const Point& p, ErrorAxis axis) {
  return p.backend + " " + p.setting.label() + " (" + threeDigits(p.milliseconds) + " ms, " +
         threeDigits(chartedError(p.error, axis)) + ")";
}

const Point* fastestBelow(const std::vector<Point>& points, ErrorAxis axis, double threshold,
                          const std::string& backend = {}) {
  const Point* best = nullptr;
  for (const Point& p : points)
    if ((backend.empty() || p.backend == backend) && chartedError(p.error, axis) <= threshold &&
        (!best || p.milliseconds < best->milliseconds))
      best = &p;
  return best;
}

// Two to four sentences read off the measured points: who holds the
// frontier's ends, who is fastest at the "good enough" error, and how the
// backends compare there.
std::string findings(const Scenario& s, const std::vector<Point>& points, const std::vector<const Point*>& frontier) {
  std::ostringstream text;
  if (frontier.size() == 1)
    text << describe(*frontier.front(), s.axis) << " is both the fastest and the most accurate point. ";
  else
    text << "The fastest point on the frontier is " << describe(*frontier.front(), s.axis) << "; the most accurate is "
         << describe(*frontier.back(), s.axis) << ". ";
  const double threshold = goodEnough(s.axis);
  if (const Point* winner = fastestBelow(points, s.axis, threshold)) {
    text << "At " << axisName(s.axis) << " ≤ " << cell(threshold) << " the fastest is " << describe(*winner, s.axis)
         << ".";
    for (const char* other : {"gpu", "cpu", "embree"}) {
      if (other == winner->backend) continue;
      if (const Point* rival = fastestBelow(points, s.axis, threshold, other))
        text << " The fastest " << other << " point there, " << describe(*rival, s.axis) << ", takes "
             << threeDigits(rival->milliseconds / winner->milliseconds) << "× as long.";
      else if (std::any_of(points.begin(), points.end(), [&](const Point& p) { return p.backend == other; }))
        text << " No " << other << " point reaches it.";
    }
  } else {
    text << "No point reaches " << axisName(s.axis) << " ≤ " << cell(threshold) << ".";
  }
  return text.str();
}

// The render shown beside the reference: the fastest facet render that is
// good enough, else the most accurate one (Embree returns depth, no image).
const Point& shownRender(const std::vector<Point>& points, ErrorAxis axis) {
  const Point *fastest = nullptr, *mostAccurate = nullptr;
  for (const Point& p : points) {
    if (p.image.pixelCount() == 0) continue;
    const double error = chartedError(p.error, axis);
    if (error <= goodEnough(axis) && (!fastest || p.milliseconds < fastest->milliseconds)) fastest = &p;
    if (!mostAccurate || error < chartedError(mostAccurate->error, axis)) mostAccurate = &p;
  }
  return fastest ? *fastest : *mostAccurate;
}

void reportScenario(const Scenario& s, const std::vector<Point>& points, const Image& reference,
                    const fs::path& directory, const std::string& relative, const std::string& subtitle,
                    const std::string& notes, Report& report) {
  const std::vector<const Point*> frontier = paretoFrontier(points, s.axis);
  writePointsCsv(directory / ("pareto_" + s.name + ".csv"), s.name, points);
  writeChart(directory, s, points, frontier, subtitle);

  const float exposure = middleGreyExposure(reference);
  writePng(directory / ("pareto_" + s.name + "_reference.png"), reference, exposure);
  const Point& shown = shownRender(points, s.axis);
  const bool shownIsGoodEnough = chartedError(shown.error, s.axis) <= goodEnough(s.axis);

  report.heading("Pareto: " + s.name);
  report.paragraph(s.description + ". " + subtitle + ". CSV: [" + relative + "/pareto_" + s.name + ".csv](" + relative +
                   "/pareto_" + s.name + ".csv). " + notes);
  report.image(relative + "/pareto_" + s.name + ".svg", s.name + ": time against " + axisName(s.axis));
  report.image(relative + "/pareto_" + s.name + "_reference.png", "reference");
  writePng(directory / ("pareto_" + s.name + "_fastest.png"), shown.image, exposure);
  report.image(relative + "/pareto_" + s.name + "_fastest.png", shown.backend + " " + shown.setting.label());
  report.paragraph("Above: the reference, then " + shown.backend + " " + shown.setting.label() + ", " +
                   (shownIsGoodEnough ? "the fastest render with " : "the most accurate render (none reaches ") +
                   axisName(s.axis) + " ≤ " + cell(goodEnough(s.axis)) + (shownIsGoodEnough ? "" : ")") +
                   ", at the same exposure.");
  std::vector<std::vector<std::string>> rows;
  for (const Point* p : frontier)
    rows.push_back({p->backend, p->setting.label(), threeDigits(p->milliseconds),
                    threeDigits(chartedError(p->error, s.axis)), threeDigits(p->error.depthRelativeMax),
                    std::to_string(p->error.holes)});
  report.table({"backend", "method", "ms", axisName(s.axis), "depth rel. max", "holes"}, rows);
  report.paragraph(findings(s, points, frontier));
}

}  // namespace

void runPareto(Renderer& renderer, const BenchOptions& options, Report& report) {
  const Sizes sizes = sizesFor(options.quick);
  const std::string relative = "pareto";
  const fs::path directory = options.output / relative;
  fs::create_directories(directory);

  report.heading("Speed against accuracy");
  std::string intro =
      "Per scene, every method and knob on both backends against a converged reference (CPU, exact, default "
      "ε = 1e-9 of each object's diagonal, same samples per pixel; sampled IBL with N = " +
      std::to_string(sizes.referenceSamples) + " pairs on the IBL scene). Time: the median of " +
      std::to_string(options.repeats) +
      " run(s) after an untimed one, of every stage but refinement + BVH and the environment's preparation (GPU "
      "timestamps on the GPU). Error: over pixels both images cover. The dashed line joins the non-dominated "
      "points; errors of 0 are drawn at " +
      cell(kChartFloor) + ".";
#if FACET_HAVE_EMBREE
  intro +=
      " Embree 3 (RTC_GEOMETRY_TYPE_SUBDIVISION, rtcIntersect1 on 2 threads, tessellation rate swept) casts the "
      "same camera rays at the torture cages; its time is primary rays alone (facet's also shades and casts "
      "shadow rays), its error depth alone.";
#else
  intro += " Embree 3 was not found when facet was built (Debian libembree-dev): no peer points.";
#endif
  report.paragraph(intro);

  for (const Scenario& s : scenarios(options, sizes)) {
    const RenderReport reference = renderReference(renderer, s);
    std::printf("pareto %s %dx%d: reference %.0f ms\n", s.name.c_str(), s.scene.render.width, s.scene.render.height,
                traceMilliseconds(reference));
    const double floor = gpuToleranceFloor(s.scene);
    std::vector<Point> points;
    std::vector<std::string> skipped;
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
      bool floorMeasured = false;
      for (const Setting& setting : s.settings) {
        // Below the float floor the GPU renders the floor: one point says it.
        if (backend == Backend::Gpu && setting.method == "exact" && setting.value < floor) {
          if (floorMeasured) {
            skipped.push_back(cell(setting.value));
            continue;
          }
          floorMeasured = true;
        }
        points.push_back(measure(renderer, s, setting, backend, reference.image, options));
        const Point& p = points.back();
        std::printf("  %-4s %-22s %9.1f ms  %s %.3g\n", p.backend.c_str(), p.setting.label().c_str(), p.milliseconds,
                    axisName(s.axis).c_str(), chartedError(p.error, s.axis));
        std::fflush(stdout);
      }
    }
    std::string embreeNotes;
#if FACET_HAVE_EMBREE
    if (s.embreePeer) {
      EmbreeRun run = measureEmbree(s, sizes, reference.image, options);
      embreeNotes = "; Embree: primary rays alone" + (run.notes.empty() ? "" : ", " + run.notes);
      for (Point& p : run.points) {
        std::printf("  %-4s %-22s %9.1f ms  %s %.3g\n", p.backend.c_str(), p.setting.label().c_str(), p.milliseconds,
                    axisName(s.axis).c_str(), chartedError(p.error, s.axis));
        points.push_back(std::move(p));
      }
    }
#endif
    std::string subtitle = std::to_string(s.scene.render.width) + "x" + std::to_string(s.scene.render.height) +
                           ", median of " + std::to_string(options.repeats) + "; reference: CPU exact" +
                           (s.referenceSamples > 0 ? ", sampled N=" + std::to_string(s.referenceSamples) : "");
    subtitle += embreeNotes;
    if (!skipped.empty()) {
      subtitle += "; GPU exact below its float floor ε ≈ " + threeDigits(floor) + " not run (";
      for (std::size_t i = 0; i < skipped.size(); ++i) subtitle += (i ? ", " : "") + skipped[i];
      subtitle += ": the same render as the first below it)";
    }
    const bool hasExact = std::any_of(s.settings.begin(), s.settings.end(),
                                      [](const Setting& setting) { return setting.method == "exact"; });
    const std::string floorNote =
        hasExact ? "The GPU's exact method accepts roots within at least ε ≈ " + threeDigits(floor) +
                       " of the diagonal here (8 float ulps of the largest coordinate); below that its renders do "
                       "not change."
                 : "";
    reportScenario(s, points, reference.image, directory, relative, subtitle, floorNote, report);
  }
}

}  // namespace facet::analysis::bench

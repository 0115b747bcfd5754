// facet bench, section "cycles": Blender Cycles beside facet on the material
// preview (the gold cube, Catmull-Clark, lit by the courtyard alone), both
// against one converged facet reference: Cycles' error and render time per
// sample count, facet's curves, and facet's time to Cycles' error. Blender
// is optional: without it the section prints a note and is skipped.
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

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
#include "analysis/gnuplot.h"
#include "engine/image/exr_file.h"
#include "engine/image/image_io.h"
#include "rules/rules.h"
#include "scenes/scene_file.h"

extern char** environ;

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

struct Sizes {
  int size;
  std::vector<int> cyclesSamples;
  int cyclesTarget;  // the sample count whose error facet is asked to reach
  std::vector<FacetCurve> curves;
  int referenceCameraSamples, referencePairs;
};

Sizes sizesFor(bool quick) {
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

// Cycles' equirectangular map looks down Blender's +x at its centre, which
// is facet's map turned by 270 degrees about +y.
constexpr double kCyclesMapRotationDegrees = 270;
constexpr int kSubdivisionLevels = 7;

bool isExecutable(const fs::path& path) { return fs::is_regular_file(path) && access(path.c_str(), X_OK) == 0; }

// FACET_BLENDER, else `blender` on PATH; nothing when neither exists.
std::optional<fs::path> findBlender() {
  if (const char* named = std::getenv("FACET_BLENDER"); named && *named) {
    if (!isExecutable(named))
      throw std::invalid_argument(std::string("FACET_BLENDER '") + named + "': not an executable file");
    return fs::path(named);
  }
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');)
    if (!folder.empty() && isExecutable(fs::path(folder) / "blender")) return fs::path(folder) / "blender";
  return std::nullopt;
}

// Runs `argv` with stdout and stderr into `log`; throws unless it exits 0.
void runLogged(const std::vector<std::string>& argv, const fs::path& log) {
  std::vector<char*> pointers;
  for (const std::string& a : argv) pointers.push_back(const_cast<char*>(a.c_str()));
  pointers.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawnError = posix_spawn(&pid, pointers[0], &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawnError != 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(spawnError));
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(argv[0] + " failed (status " + std::to_string(status) + "); see " + log.string());
}

void writeObj(const fs::path& path, const scene::ControlCage& cage) {
  std::ofstream obj(path);
  obj.precision(17);
  for (const glm::dvec3& p : cage.positions) obj << "v " << p.x << " " << p.y << " " << p.z << "\n";
  std::size_t at = 0;
  for (int count : cage.faceVertexCounts) {
    obj << "f";
    for (int i = 0; i < count; ++i) obj << " " << cage.faceVertexIndices[at++] + 1;
    obj << "\n";
  }
  if (!obj) throw std::runtime_error(path.string() + ": cannot write");
}

std::string formatted(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string joined(const std::vector<int>& values) {
  std::string text;
  for (int v : values) {
    if (!text.empty()) text += ',';
    text += std::to_string(v);
  }
  return text;
}

// Per sample count, the median of Cycles' timed render calls (seconds).
std::map<int, double> readCyclesTimes(const fs::path& csv) {
  std::ifstream in(csv);
  std::map<int, std::vector<double>> runs;
  std::string line;
  std::getline(in, line);  // header
  for (int samples; std::getline(in, line);)
    if (double seconds; std::sscanf(line.c_str(), "%d,%lf", &samples, &seconds) == 2) runs[samples].push_back(seconds);
  std::map<int, double> medians;
  for (const auto& [samples, seconds] : runs) medians[samples] = median(seconds);
  return medians;
}

// Mean beauty per channel over the pixels `reference` covers.
glm::dvec3 coveredMean(const Image& image, const Image& reference) {
  glm::dvec3 sum(0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i)
    if (covered(reference, i)) sum += glm::dvec3(image.beauty[i]), ++count;
  return sum / double(std::max<std::size_t>(count, 1));
}

struct Point {
  std::string curve;
  int samples = 0;  // Cycles: samples per pixel; facet: pairs per camera sample
  double milliseconds = 0;
  double relativeRmse = 0;
};

// The time at which a curve, ordered by N, first reaches `error`:
// interpolated linearly in log time against log error between its
// neighbouring points; nothing when it never does.
std::optional<double> timeToError(const std::vector<Point>& curve, double error) {
  for (std::size_t i = 0; i < curve.size(); ++i) {
    if (curve[i].relativeRmse > error) continue;
    if (i == 0) return curve[0].milliseconds;
    const Point &a = curve[i - 1], &b = curve[i];
    const double t = std::log(error / a.relativeRmse) / std::log(b.relativeRmse / a.relativeRmse);
    return std::exp(std::log(a.milliseconds) + t * std::log(b.milliseconds / a.milliseconds));
  }
  return std::nullopt;
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
  scene::Scene scene = scene::loadScene(root / "scenes/examples/gold_cube.gltf");
  scene::overrideSubdivision(scene, "catmull-clark", "cycles");
  scene.lights.clear();
  scene.environment.emplace();
  scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(map));
  scene.environment->rotationDegrees = kCyclesMapRotationDegrees;
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

// The same scene for tools/blender/material_preview.py, in facet's coordinates.
std::vector<std::string> blenderArguments(const fs::path& blender, const fs::path& script, const fs::path& cage,
                                          const fs::path& map, const scene::Scene& scene, const Sizes& sizes,
                                          int repeats, unsigned threads, const fs::path& directory) {
  const scene::Camera& camera = scene.camera;
  const materials::Material& metal = scene.materials.at(std::size_t(scene.objects.at(0).material));
  std::vector<std::string> argv{blender.string(), "-b", "--factory-startup", "-t", std::to_string(threads)};
  argv.insert(argv.end(), {"--python", script.string(), "--", "--cage", cage.string(), "--env", map.string()});
  argv.insert(argv.end(),
              {"--intensity", cell(scene.environment->intensity), "--fov", cell(camera.verticalFovDegrees)});
  for (const auto& [flag, v] : {std::pair{"--eye", camera.eye}, std::pair{"--target", camera.target},
                                std::pair{"--up", camera.up}, std::pair{"--f0", metal.f0}})
    argv.insert(argv.end(), {flag, cell(v.x), cell(v.y), cell(v.z)});
  argv.insert(argv.end(), {"--size", std::to_string(sizes.size), std::to_string(sizes.size), "--roughness",
                           cell(std::sqrt(metal.alpha)), "--levels", std::to_string(kSubdivisionLevels)});
  argv.insert(argv.end(), {"--threads", std::to_string(threads), "--samples", joined(sizes.cyclesSamples), "--repeats",
                           std::to_string(repeats), "--output", directory.string()});
  return argv;
}

// Cycles' points, from the images and times the script wrote; `converged`
// gets the image of the largest sample count.
std::vector<Point> cyclesPoints(const fs::path& directory, const Sizes& sizes, const Image& reference,
                                Image& converged) {
  const std::map<int, double> seconds = readCyclesTimes(directory / "cycles_times.csv");
  std::vector<Point> points;
  for (int samples : sizes.cyclesSamples) {
    const Image written = readExr(directory / ("cycles_" + std::to_string(samples) + "spp.exr"));
    if (written.width != reference.width || written.height != reference.height)
      throw std::runtime_error("cycles: Cycles' image is not " + std::to_string(sizes.size) + " square");
    // Cycles writes beauty alone; its surface is facet's, so the reference's
    // AOVs (coverage, depth, normals) stand for its own.
    converged = reference;
    converged.beauty = written.beauty;
    points.push_back(
        {"Cycles", samples, 1000 * seconds.at(samples), compareToReference(converged, reference).relativeRmse});
    std::printf("  cycles %4d spp          %9.1f ms  relative RMSE %.3g\n", samples, points.back().milliseconds,
                points.back().relativeRmse);
  }
  return points;
}

// facet's curves, each point the median time of `repeats` after an untimed run per curve.
std::vector<std::vector<Point>> facetCurves(Renderer& renderer, const scene::Scene& scene, const Sizes& sizes,
                                            int repeats, const Image& reference) {
  for (const FacetCurve& c : sizes.curves)
    renderPreview(renderer, scene, c.method, c.cameraSamples, c.pairs.front(), 0);
  std::vector<std::vector<Point>> curves;
  for (const FacetCurve& c : sizes.curves) {
    std::vector<Point>& curve = curves.emplace_back();
    for (int pairs : c.pairs) {
      Image image;
      const double ms = medianMilliseconds(repeats, [&] {
        RenderReport r = renderPreview(renderer, scene, c.method, c.cameraSamples, pairs, 0);
        image = std::move(r.image);
        return traceMilliseconds(r);
      });
      curve.push_back({curveName(c), pairs, ms, compareToReference(image, reference).relativeRmse});
      std::printf("  facet %-17s N=%-4d %9.1f ms  relative RMSE %.3g\n", curveName(c).c_str(), pairs, ms,
                  curve.back().relativeRmse);
      std::fflush(stdout);
    }
  }
  return curves;
}

// The fastest facet curve's time to `target`'s error, as a sentence.
std::string verdict(const std::vector<std::vector<Point>>& curves, const Point& target) {
  std::optional<double> fastest;
  std::string fastestCurve;
  for (const std::vector<Point>& curve : curves)
    if (const std::optional<double> t = timeToError(curve, target.relativeRmse); t && (!fastest || *t < *fastest))
      fastest = t, fastestCurve = curve.front().curve;
  char text[256];
  if (fastest)
    std::snprintf(text, sizeof text,
                  "facet reaches Cycles' %d-spp error (%.3g) in %.0f ms (%s, interpolated): %.2fx Cycles' %.0f ms",
                  target.samples, target.relativeRmse, *fastest, fastestCurve.c_str(), *fastest / target.milliseconds,
                  target.milliseconds);
  else
    std::snprintf(text, sizeof text, "facet does not reach Cycles' %d-spp error (%.3g) on any measured curve",
                  target.samples, target.relativeRmse);
  return text;
}

}  // namespace

void runCycles(Renderer& renderer, const BenchOptions& options, Report& report) {
  report.heading("Cycles: the material preview");
  const fs::path script = options.root / "tools/blender/material_preview.py";
  const std::optional<fs::path> blender = findBlender();
  if (!blender || !fs::exists(script)) {
    const std::string note =
        !blender ? "blender is not on PATH and FACET_BLENDER is unset" : script.string() + " is not under --root";
    std::printf("cycles: skipped: %s\n", note.c_str());
    report.paragraph("Skipped: " + note + ".");
    return;
  }
  const Sizes sizes = sizesFor(options.quick);
  const fs::path directory = options.output / "cycles";
  fs::create_directories(directory);
  const fs::path map = options.root / "scenes/environments/courtyard_256x128.hdr";
  const scene::Scene scene = materialPreview(options.root, map, sizes.size);

  // Its own random numbers: sharing the estimates' would under-report their error.
  const Image reference =
      renderPreview(renderer, scene, scene::IblMethod::Sampled, sizes.referenceCameraSamples, sizes.referencePairs, 1)
          .image;
  writeExr(directory / "facet_reference.exr", reference);

  // Cycles runs on as many threads as lavapipe.
  const char* lavapipe = std::getenv("LP_NUM_THREADS");
  const unsigned threads =
      lavapipe && std::atoi(lavapipe) > 0 ? unsigned(std::atoi(lavapipe)) : std::thread::hardware_concurrency();
  const fs::path cage = directory / "cage.obj";
  writeObj(cage, scene.objects.at(0).cage);
  std::printf("cycles: rendering with %s on %u threads\n", blender->c_str(), threads);
  std::fflush(stdout);
  runLogged(blenderArguments(*blender, script, cage, map, scene, sizes, options.repeats, threads, directory),
            directory / "blender.log");
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
      blender->string() + ", " + std::to_string(threads) +
      " threads, tools/blender/material_preview.py): the cage subdivided " + std::to_string(kSubdivisionLevels) +
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

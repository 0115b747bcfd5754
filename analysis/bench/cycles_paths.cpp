// facet bench, section "bounces": scenes whose light bounces (the gold
// teacup, glass and ruby over a diffuse floor) traced by facet's paths and by
// Blender Cycles with the same bounce limits. Their converged images are
// compared per pixel against the noise each still holds, and on the teacup
// facet's time to Cycles' error is measured. Blender is optional: without it
// the section prints a note and is skipped.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/bench/cycles_sections.h"
#include "engine/image/exr_file.h"
#include "engine/image/image_io.h"
#include "rules/rules.h"
#include "scenes/scene_file.h"

namespace facet::analysis::bench {
namespace {

namespace fs = std::filesystem;

struct PathSizes {
  int width;                       // the teacup's square; the glass scene is twice as wide
  std::vector<int> cyclesSamples;  // timed, for the teacup's time to error
  int cyclesTarget;                // the sample count whose error facet is asked to reach
  int cyclesConverged;             // each of Cycles' two converged images
  int facetConverged;              // camera samples of one of facet's converged renders
  int facetRenders;                // renders summed into each half of facet's converged image
  std::vector<int> facetSamples;   // camera samples of the timed renders
};

PathSizes pathSizesFor(bool quick) {
  if (quick) return {24, {4}, 4, 16, 16, 1, {1, 4}};
  return {96, {4, 16, 64, 256}, 64, 2048, 1024, 1, {1, 4, 16, 64, 256}};
}

// Cycles' defaults (max 12, diffuse 4, glossy 4, transmission 12), both sides.
void cyclesBounces(scene::RenderSettings& render) {
  render.bounces = 12;
  render.diffuseBounces = 4;
  render.glossyBounces = 4;
  render.transmissionBounces = 12;
}

// The environment as Cycles sees it, sampled with one pair per vertex and shadowed.
void cyclesEnvironment(scene::Scene& scene) {
  scene::Environment& environment = scene.environment.value();
  environment.rotationDegrees = peers::kCyclesMapRotationDegrees;
  environment.method = scene::IblMethod::Sampled;
  environment.samples = 1;
  environment.occlusion = true;
}

// Newell's teacup in rough gold (scenes/examples/teacup.json), in the models
// Cycles' plain GGX Principled metallic has.
scene::Scene teacup(const fs::path& root, int size) {
  scene::Scene scene = scene::loadScene(root / "scenes/examples/teacup.json");
  cyclesEnvironment(scene);
  cyclesBounces(scene.render);
  scene.render.width = scene.render.height = size;
  scene.render.method = scene::IntersectionMethod::Exact;
  for (materials::Material& m : scene.materials) {
    m.geometry = rules::f64::G_SMITH_GGX;
    m.fresnel = rules::f64::F_BLENDER_METALLIC;
  }
  return scene;
}

// Clear glass, thick and thin ruby (scenes/examples/glass.json) over a
// Lambert floor of albedo 0.5: the dielectric Fresnel of index 1 has no
// specular lobe, which Cycles' Diffuse BSDF lacks too.
scene::Scene glass(const fs::path& root, int width) {
  scene::Scene scene = scene::loadScene(root / "scenes/examples/glass.json");
  cyclesEnvironment(scene);
  cyclesBounces(scene.render);
  scene.render.width = width;
  scene.render.height = width / 2;
  scene.render.method = scene::IntersectionMethod::Exact;
  for (materials::Material& m : scene.materials)
    if (!materials::isTransmissive(m)) {
      m.fresnel = rules::f64::F_DIELECTRIC;
      m.eta = glm::dvec3(1.0);
      m.diffuse = glm::dvec3(0.5);
    }
  return scene;
}

RenderReport render(Renderer& renderer, scene::Scene scene, int cameraSamples, std::uint32_t seed) {
  scene.render.samplesPerPixel = cameraSamples;
  scene.environment->seed = seed;
  return renderer.render(scene, Backend::Gpu);
}

// Pixel by pixel (a + b) / 2; the AOVs are a's.
Image average(const Image& a, const Image& b) {
  Image mean = a;
  for (std::size_t i = 0; i < a.pixelCount(); ++i) mean.beauty[i] = 0.5f * (a.beauty[i] + b.beauty[i]);
  return mean;
}

// facet's converged image as two independent halves, each the mean of
// `renders` GPU renders under seeds of its own.
std::pair<Image, Image> facetHalves(Renderer& renderer, const scene::Scene& scene, const PathSizes& sizes) {
  std::vector<Image> halves;
  std::uint32_t seed = 1;
  for (int half = 0; half < 2; ++half) {
    Image sum = render(renderer, scene, sizes.facetConverged, seed++).image;
    for (int r = 1; r < sizes.facetRenders; ++r) {
      const Image next = render(renderer, scene, sizes.facetConverged, seed++).image;
      for (std::size_t i = 0; i < sum.pixelCount(); ++i) sum.beauty[i] += next.beauty[i];
    }
    for (glm::vec4& b : sum.beauty) b /= float(sizes.facetRenders);
    halves.push_back(std::move(sum));
  }
  return {halves[0], halves[1]};
}

// One scale of the comparison.
struct Difference {
  double relativeRmse;  // facet's converged image against Cycles'
  double noise;         // what their noise alone would give (from each renderer's two halves)
  double rest;          // sqrt(max(0, rmse^2 - noise^2)): what noise does not explain
};

Difference difference(const std::pair<Image, Image>& facet, const std::pair<Image, Image>& cycles, int block) {
  const Image facetMean = average(facet.first, facet.second), cyclesMean = average(cycles.first, cycles.second);
  // The difference of two halves has twice the variance of one half, which
  // has twice that of their mean: the mean's noise is half the halves' RMSE.
  const double facetNoise = blockRelativeRmse(facet.first, facet.second, facetMean, block) / 2;
  const double cyclesNoise = blockRelativeRmse(cycles.first, cycles.second, facetMean, block) / 2;
  Difference d;
  d.relativeRmse = blockRelativeRmse(cyclesMean, facetMean, facetMean, block);
  d.noise = std::sqrt(facetNoise * facetNoise + cyclesNoise * cyclesNoise);
  d.rest = std::sqrt(std::max(0.0, d.relativeRmse * d.relativeRmse - d.noise * d.noise));
  return d;
}

constexpr int kBlock = 8;

std::string percent(double value) { return formatted("%+.2f%%", 100 * value); }

// facet's timed curves, exact and tessellated, each point the median of
// `repeats` renders after an untimed one, its error against `converged`.
std::vector<std::vector<Point>> timedCurves(Renderer& renderer, scene::Scene scene, const PathSizes& sizes, int repeats,
                                            const Image& converged) {
  std::vector<std::vector<Point>> curves;
  for (const scene::IntersectionMethod method :
       {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated}) {
    scene.render.method = method;
    const std::string name = method == scene::IntersectionMethod::Exact ? "exact" : "tessellated";
    render(renderer, scene, sizes.facetSamples.front(), 0);  // untimed: pipelines and caches
    std::vector<Point>& curve = curves.emplace_back();
    for (int n : sizes.facetSamples)
      curve.push_back(timedPoint(
          name, n, repeats, [&] { return render(renderer, scene, n, 100); }, converged));
  }
  return curves;
}

}  // namespace

void runCyclesPaths(Renderer& renderer, const BenchOptions& options, Report& report) {
  report.heading("Cycles: scenes that bounce");
  const std::optional<peers::CyclesPeer> peer = findCyclesPeer(options.root, "bounces", report);
  if (!peer) return;
  const PathSizes sizes = pathSizesFor(options.quick);
  struct Case {
    std::string name;
    scene::Scene scene;
    bool timed;
  };
  const std::vector<Case> cases{{"teacup", teacup(options.root, sizes.width), true},
                                {"glass", glass(options.root, 2 * sizes.width), false}};
  std::vector<std::vector<std::string>> table;
  for (const Case& c : cases) {
    const fs::path directory = options.output / "bounces" / c.name;
    fs::create_directories(directory);
    std::printf("bounces: %s: facet's converged image\n", c.name.c_str());
    std::fflush(stdout);
    const std::pair<Image, Image> facet = facetHalves(renderer, c.scene, sizes);
    const Image facetConverged = average(facet.first, facet.second);
    writeExr(directory / "facet_converged.exr", facetConverged);
    writeExr(directory / "facet_half1.exr", facet.first);
    writeExr(directory / "facet_half2.exr", facet.second);
    std::printf("bounces: %s: Cycles with %s\n", c.name.c_str(), peer->blender.c_str());
    std::fflush(stdout);
    peers::CyclesRenders renders{c.timed ? sizes.cyclesSamples : std::vector<int>{}, options.repeats,
                                 sizes.cyclesConverged};
    peers::renderInCycles(peer->blender, peer->script, peers::describeForCycles(c.scene, directory), renders,
                          directory);
    const std::pair<Image, Image> cycles{
        peers::readCyclesImage(directory / "cycles_converged_seed1.exr", facetConverged),
        peers::readCyclesImage(directory / "cycles_converged_seed2.exr", facetConverged)};
    const float exposure = middleGreyExposure(facetConverged);
    writePng(directory / "facet.png", facetConverged, exposure);
    writePng(directory / "cycles.png", average(cycles.first, cycles.second), exposure);

    const glm::dvec3 facetMean = coveredMean(facetConverged, facetConverged);
    const glm::dvec3 ratio = coveredMean(average(cycles.first, cycles.second), facetConverged) / facetMean - 1.0;
    const Difference pixels = difference(facet, cycles, 1), blocks = difference(facet, cycles, kBlock);
    std::printf(
        "  %s: Cycles / facet - 1: R %s G %s B %s; relative RMSE per pixel %.4f (noise alone %.4f, rest "
        "%.4f), per %d x %d block %.4f (noise %.4f, rest %.4f)\n",
        c.name.c_str(), percent(ratio.r).c_str(), percent(ratio.g).c_str(), percent(ratio.b).c_str(),
        pixels.relativeRmse, pixels.noise, pixels.rest, kBlock, kBlock, blocks.relativeRmse, blocks.noise, blocks.rest);
    table.push_back({c.name, percent(ratio.r), percent(ratio.g), percent(ratio.b),
                     formatted("%.4f", pixels.relativeRmse), formatted("%.4f", pixels.noise),
                     formatted("%.4f", pixels.rest), formatted("%.4f", blocks.relativeRmse),
                     formatted("%.4f", blocks.noise), formatted("%.4f", blocks.rest)});
    if (!c.timed) continue;

    // Time to Cycles' error, both against facet's converged image.
    const std::map<int, double> seconds = peers::readCyclesTimes(directory / "cycles_times.csv", sizes.cyclesSamples);
    std::vector<std::vector<Point>> curves(1);
    for (int n : sizes.cyclesSamples) {
      const Image image =
          peers::readCyclesImage(directory / ("cycles_" + std::to_string(n) + "spp.exr"), facetConverged);
      curves[0].push_back({"Cycles", n, 1000 * seconds.at(n), compareToReference(image, facetConverged).relativeRmse});
    }
    const std::vector<std::vector<Point>> facetCurves =
        timedCurves(renderer, c.scene, sizes, options.repeats, facetConverged);
    curves.insert(curves.end(), facetCurves.begin(), facetCurves.end());
    std::vector<std::vector<std::string>> timing;
    for (const std::vector<Point>& curve : curves)
      for (const Point& p : curve)
        timing.push_back({p.curve == "Cycles" ? p.curve : "facet " + p.curve, std::to_string(p.samples),
                          formatted("%.1f", p.milliseconds), formatted("%.4f", p.relativeRmse)});
    writeCsv(directory / "time_to_error.csv", {"renderer", "spp", "milliseconds", "relative_rmse"}, timing);
    const Point& target = *std::find_if(curves[0].begin(), curves[0].end(),
                                        [&](const Point& p) { return p.samples == sizes.cyclesTarget; });
    const std::string sentence = verdict(facetCurves, target);
    std::printf("  %s: %s\n", c.name.c_str(), sentence.c_str());
    report.paragraph("Teacup: " + sentence + ".");
    report.table({"renderer", "spp", "ms (facet: GPU tracing stages; Cycles: render call)", "relative RMSE"}, timing);
  }
  report.paragraph(
      "Cycles (" + peer->blender.string() + ", " + std::to_string(peers::cyclesThreads()) +
      " threads, tools/blender/cycles_scene.py) and facet (GPU backend) with Cycles' default bounce limits (12; "
      "diffuse 4, glossy 4, transmission 12), the courtyard sampled, no clamping or denoising. Converged: facet " +
      std::to_string(2 * sizes.facetRenders) + " renders of " + std::to_string(sizes.facetConverged) +
      " spp in two halves, Cycles two seeds of " + std::to_string(sizes.cyclesConverged) +
      " spp. Means and relative RMSE over the pixels facet covers, per pixel and per 8 x 8 block of them; 'noise "
      "alone' is what the two images' remaining noise would give (from each renderer's halves), 'rest' what it "
      "leaves unexplained.");
  report.table({"scene", "Cycles/facet-1 R", "G", "B", "relative RMSE per pixel", "noise alone", "rest",
                "per 8x8 block", "noise alone", "rest"},
               table);
}

}  // namespace facet::analysis::bench

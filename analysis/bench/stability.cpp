// facet bench, section "stability": where each method fails. Each sweep
// pushes one condition (grazing view, roughness, valence, crease sharpness,
// scale, distance from the origin, the environment's dynamic range) and
// renders small images with every method, each compared against the CPU
// exact reference (double precision) at the same condition
// (stability_map.h for what counts as a failure).
#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/bench/stability_map.h"
#include "analysis/bench/stability_runner.h"
#include "analysis/bench/stability_scenes.h"
#include "scenes/scene_file.h"

namespace facet::analysis::bench {
namespace {

using scene::IblMethod;
using scene::IntersectionMethod;
using namespace stability;

std::vector<Method> geometryMethods() {
  return {{"gpu exact", Backend::Gpu, IntersectionMethod::Exact, ""},
          {"gpu tess k=8", Backend::Gpu, IntersectionMethod::Tessellated, ""},
          {"cpu exact", Backend::Cpu, IntersectionMethod::Exact, ""},
          {"cpu tess k=8", Backend::Cpu, IntersectionMethod::Tessellated, ""}};
}

std::vector<std::string> labelsOf(const std::vector<Method>& methods) {
  std::vector<std::string> labels;
  for (const Method& m : methods) labels.push_back(m.label);
  return labels;
}

std::string shortLabel(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// A sweep's names and its condition's values, each labelled as written.
Sweep sweepOf(const std::string& name, const std::string& title, const std::string& condition,
              std::vector<double> values) {
  Sweep s;
  s.name = name;
  s.title = title;
  s.condition = condition;
  s.values = std::move(values);
  for (double v : s.values) s.valueLabels.push_back(shortLabel(v));
  return s;
}

void setIbl(scene::Scene& scene, const std::string& lighting) {
  scene.environment->method = lighting == "prefiltered" ? IblMethod::Prefiltered : IblMethod::Sampled;
}

std::vector<Method> iblMethods(bool withTessellated) {
  std::vector<Method> methods;
  for (Backend backend : {Backend::Gpu, Backend::Cpu})
    for (IntersectionMethod intersection : {IntersectionMethod::Exact, IntersectionMethod::Tessellated}) {
      if (intersection == IntersectionMethod::Tessellated && !withTessellated) continue;
      for (const char* ibl : {"sampled", "prefiltered"})
        methods.push_back({std::string(backend == Backend::Gpu ? "gpu" : "cpu") +
                               (intersection == IntersectionMethod::Exact ? " exact " : " tess k=8 ") + ibl,
                           backend, intersection, ibl});
    }
  return methods;
}

void grazing(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf("stability_grazing", "grazing view", "view angle from the normal (deg)",
                    runner.quick() ? std::vector<double>{0, 89, 89.99}
                                   : std::vector<double>{0, 60, 80, 85, 88, 89, 89.5, 89.9, 89.99, 89.999});
  const std::vector<Method> methods = iblMethods(true);
  s.rows = labelsOf(methods);
  s.metrics = {"beauty_max", "beauty_mean", "relative_rmse", "depth_rel_max"};
  std::ostringstream setup;
  setup << "A flat 8 x 8 quad cage (12 units wide) seen from 3 units at an angle from its normal (n·v of the "
           "centre ray: ";
  for (double angle : s.values) {
    setup << shortLabel(std::cos(angle * std::numbers::pi / 180)) << (angle == s.values.back() ? "" : ", ");
  }
  setup << "), 30° field of view, so each image also holds the other n·v within ±15° of elevation around the "
           "centre ray's (from 89° on: n·v from 0 at the plane's horizon to about 0.27). Lit only by a white furnace "
           "(constant environment of radiance 1, occlusion on, "
           "sampled N = 16 or prefiltered) on a white metal (Schlick F0 = 1, GGX alpha 0.25): no pixel may exceed "
           "1 (`beauty_max`; sampled pixels are noisy, so for them only `beauty_mean` is bound). Each method is "
           "compared with "
           "the CPU exact render using the same IBL method. "
        << methodsText(runner.tolerances());
  s.setup = setup.str();
  for (std::size_t column = 0; column < s.values.size(); ++column) {
    scene::Scene scene = runner.sceneOf(planeCage());
    const double angle = s.values[column] * std::numbers::pi / 180;
    scene.camera.target = glm::dvec3(0.0);
    scene.camera.eye = 3.0 * glm::dvec3(0.0, std::cos(angle), std::sin(angle));
    scene.camera.up = glm::dvec3(0.0, std::sin(angle), -std::cos(angle));
    scene.camera.verticalFovDegrees = 30;
    scene.lights.clear();
    scene.materials = {metal(0.25, glm::dvec3(1.0))};
    scene.environment = environmentOf(scene::constantEnvironment(glm::dvec3(1.0)));
    runner.run(s, column, scene, methods, setIbl, true);
  }
  sweeps.push_back(std::move(s));
}

void roughness(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf(
      "stability_roughness", "roughness", "GGX alpha",
      runner.quick() ? std::vector<double>{1e-1, 1e-3, 0} : std::vector<double>{1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 0});
  std::vector<Method> methods;
  for (Backend backend : {Backend::Gpu, Backend::Cpu})
    for (const char* lighting : {"point light", "sunrise sampled", "sunrise prefiltered"})
      methods.push_back({std::string(backend == Backend::Gpu ? "gpu " : "cpu ") + lighting, backend,
                         IntersectionMethod::Exact, lighting});
  s.rows = labelsOf(methods);
  s.metrics = {"relative_rmse", "firefly_ratio"};
  s.setup =
      "The cube cage's limit surface (a rounded blob), exact ray casting, a gold-like metal (Schlick F0 = (0.95, "
      "0.64, 0.54), GGX) whose alpha goes below the 1e-3 clamp (docs/shading.md: alpha is raised to 1e-3, so "
      "1e-4, 1e-5 and 0 must render as 1e-3 does). Lit by a point light alone, or by `sunrise.exr` alone (sun near "
      "3e4; sampled N = 16 with occlusion, or prefiltered). Each GPU render is compared with the CPU render of the "
      "same lighting; `firefly_ratio` is the largest covered pixel channel over the mean (a measure of how "
      "concentrated the highlight is, not a failure by itself). " +
      methodsText(runner.tolerances());
  const auto sunrise = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(runner.root() / "scenes/environments/sunrise.exr"));
  auto light = [&](scene::Scene& scene, const std::string& lighting) {
    if (lighting == "point light") {
      scene::Light point;
      point.type = scene::LightType::Point;
      point.position = scene.camera.eye + glm::dvec3(2.0, 3.0, -1.0);
      point.color = glm::dvec3(30.0);
      scene.lights = {point};
      return;
    }
    scene.lights.clear();
    scene::Environment environment;
    environment.map = sunrise;
    environment.method = lighting == "sunrise prefiltered" ? IblMethod::Prefiltered : IblMethod::Sampled;
    scene.environment = environment;
  };
  for (std::size_t column = 0; column < s.values.size(); ++column) {
    scene::Scene scene = runner.sceneOf(cubeCage());
    scene.materials = {metal(s.values[column], {0.95, 0.64, 0.54})};
    runner.run(s, column, scene, methods, light, false);
  }
  sweeps.push_back(std::move(s));
}

// Sweeps a geometric condition with the four geometry methods under the
// default key light and material.
void geometrySweep(Runner& runner, std::vector<Sweep>& sweeps, Sweep s,
                   const std::function<scene::Scene(double)>& sceneAt) {
  const std::vector<Method> methods = geometryMethods();
  s.rows = labelsOf(methods);
  s.setup += " Default grey plastic under the default key light. " + methodsText(runner.tolerances());
  for (std::size_t column = 0; column < s.values.size(); ++column)
    runner.run(s, column, sceneAt(s.values[column]), methods, {}, true);
  sweeps.push_back(std::move(s));
}

void valence(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf("stability_valence", "valence of extraordinary vertices", "pole valence",
                    runner.quick() ? std::vector<double>{3, 12} : std::vector<double>{3, 4, 5, 6, 8, 10, 12, 16, 24});
  s.metrics = {"normal_rad_max", "depth_rel_max"};
  s.setup =
      "A closed quad cage with two poles of valence n (the other vertices are valence 3 or 4 for every n), "
      "viewed close up from above one pole (25° field of view), so the Gregory end caps around it fill the image.";
  geometrySweep(runner, sweeps, std::move(s), [&](double n) {
    scene::Scene scene = runner.sceneOf(poleCage(int(n)));
    scene.camera.target = glm::dvec3(0.0, 0.9, 0.0);
    scene.camera.eye = scene.camera.target + 2.5 * glm::normalize(glm::dvec3(0.4, 1.0, 0.7));
    scene.camera.verticalFovDegrees = 25;
    scene.lights = {scene::defaultKeyLight(scene.camera)};
    return scene;
  });
}

void crease(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf("stability_crease", "crease sharpness", "crease sharpness",
                    runner.quick() ? std::vector<double>{0, 2, 10} : std::vector<double>{0, 0.5, 1, 2, 4, 8, 10});
  s.metrics = {"depth_rel_max", "normal_rad_max"};
  s.setup =
      "The cube cage with its four top edges creased as one loop (sharpness 10 is infinitely sharp), framed by "
      "the default view.";
  geometrySweep(runner, sweeps, std::move(s), [&](double sharpness) { return runner.sceneOf(creasedCube(sharpness)); });
}

void scale(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf("stability_scale", "object scale", "scale factor",
                    runner.quick() ? std::vector<double>{1e-16, 1, 1e16}
                                   : std::vector<double>{1e-16, 1e-12, 1e-8, 1e-4, 1, 1e4, 1e8, 1e12, 1e16});
  s.metrics = {"depth_rel_max", "normal_rad_max"};
  s.setup =
      "The cube cage scaled about the origin, seen from the default view of the unscaled cage scaled by the "
      "same factor (so the image is the same).";
  const scene::Camera unit = runner.sceneOf(cubeCage()).camera;
  geometrySweep(runner, sweeps, std::move(s), [&](double factor) {
    scene::ControlCage cage = cubeCage();
    for (glm::dvec3& p : cage.positions) p *= factor;
    scene::Scene scene = runner.sceneOf(std::move(cage));
    // frameBounds keeps a radius of at least 1e-6, which would shrink the
    // smallest cages in the image.
    scene.camera = unit;
    scene.camera.eye *= factor;
    scene.camera.target *= factor;
    return scene;
  });
}

void distance(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf(
      "stability_distance", "distance from the origin", "distance from the origin",
      runner.quick() ? std::vector<double>{1, 1e4, 1e7} : std::vector<double>{1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7});
  s.metrics = {"depth_rel_max", "normal_rad_max"};
  s.setup =
      "The cube cage (size 2) moved along (1, 1, 1) by this distance, camera and light moved with it (the "
      "image is the same): float positions on the GPU lose digits as the coordinates grow.";
  geometrySweep(runner, sweeps, std::move(s), [&](double d) {
    scene::ControlCage cage = cubeCage();
    const glm::dvec3 offset = d * glm::normalize(glm::dvec3(1.0));
    for (glm::dvec3& p : cage.positions) p += offset;
    return runner.sceneOf(std::move(cage));
  });
}

void dynamicRange(Runner& runner, std::vector<Sweep>& sweeps) {
  Sweep s = sweepOf(
      "stability_dynamic_range", "environment dynamic range", "sun radiance (sky = 1)",
      runner.quick() ? std::vector<double>{1, 1e4, 1e8} : std::vector<double>{1, 1e2, 1e4, 1e8, 1e12, 1e16, 1e20});
  const std::vector<Method> methods = iblMethods(false);
  s.rows = labelsOf(methods);
  s.metrics = {"method_error", "relative_rmse"};
  const int convergedSamples = runner.quick() ? 256 : 4096;
  s.setup =
      "The cube cage's blob in default grey plastic (alpha 0.25), no lights, under a 64 x 32 environment: "
      "radiance 1 everywhere but a 2 x 2 texel sun (0.35% of the sphere) of the given radiance. Failures "
      "are against the CPU render of the same IBL method; `method_error` is the relative RMSE against the "
      "GPU sampled with N = " +
      std::to_string(convergedSamples) +
      " (the GPU because it is the faster, and sampled GPU and CPU agree to about 1e-4 here), the accuracy a user "
      "gets from each method. Occlusion is off for every render: the blob is convex, so it changes nothing but "
      "the cost (2N shadow rays per pixel). " +
      methodsText(runner.tolerances());
  for (std::size_t column = 0; column < s.values.size(); ++column) {
    scene::Scene scene = runner.sceneOf(cubeCage());
    scene.lights.clear();
    scene.environment = environmentOf(sunEnvironment(s.values[column]));
    scene.environment->occlusion = false;
    runner.run(s, column, scene, methods, setIbl, false, [&] {
      scene::Scene converged = scene;
      converged.environment->method = IblMethod::Sampled;
      converged.environment->samples = convergedSamples;
      return runner.render(converged, {"", Backend::Gpu, IntersectionMethod::Exact, ""});
    });
  }
  sweeps.push_back(std::move(s));
}

}  // namespace

void runStability(Renderer& renderer, const BenchOptions& options, Report& report) {
  Runner runner(renderer, options);
  std::vector<Sweep> sweeps;
  const std::vector<std::pair<const char*, std::function<void(Runner&, std::vector<Sweep>&)>>> steps{
      {"grazing", grazing}, {"roughness", roughness}, {"valence", valence},           {"crease", crease},
      {"scale", scale},     {"distance", distance},   {"dynamic range", dynamicRange}};
  const auto start = std::chrono::steady_clock::now();
  for (const auto& [name, step] : steps) {
    const auto stepStart = std::chrono::steady_clock::now();
    const int before = runner.renders();
    step(runner, sweeps);
    std::printf("stability: %s, %d renders, %.1f s\n", name, runner.renders() - before,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count());
    std::fflush(stdout);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.heading("Stability map");
  report.paragraph(
      "Where each method fails, sweep by sweep: every cell is one " + std::to_string(runner.size()) + "x" +
      std::to_string(runner.size()) +
      " render compared pixel by pixel with the CPU exact reference (double precision) at the same condition. "
      "A pixel fails when it is non-finite, a hole (the reference covers it and its 8 neighbours), extra (the "
      "reference misses it and its 8 neighbours), a Newton miss (exact methods: a dense CPU tessellation covers "
      "it and its neighbours, the ray cast found no root), or over tolerance in depth, normal or beauty; the "
      "colour is the failing share of the reference's covered pixels. All cells: `stability.csv` (" +
      std::to_string(runner.renders()) + " renders, " + cell(std::round(seconds)) + " s).");
  for (const Sweep& sweep : sweeps) stability::writeSweep(options.output, sweep, report);
  stability::writeStabilityCsv(options.output / "stability.csv", sweeps);
}

}  // namespace facet::analysis::bench

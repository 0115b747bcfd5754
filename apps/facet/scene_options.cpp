#include "scene_options.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <tuple>
#include <stdexcept>

#include "scenes/camera_rules.h"
#include "scenes/scene_file.h"

namespace facet::cli {

void applyImageSize(const std::string& size, scene::Scene& scene) {
  int w = 0, h = 0;
  char x = 0, trailing = 0;
  if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &trailing) != 3 || x != 'x' || w < 1 || h < 1 || w > 16384 ||
      h > 16384)
    throw std::invalid_argument("--size '" + size + "': expected WIDTHxHEIGHT, each in 1..16384, e.g. 512x512");
  scene.render.width = w;
  scene.render.height = h;
}

void applyMethod(const std::string& method, scene::Scene& scene) {
  scene.render.method = method == "tess" ? scene::IntersectionMethod::Tessellated : scene::IntersectionMethod::Exact;
}

namespace {

glm::dvec3 vector3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// --env replaces the scene's map and keeps its other settings; the other
// environment flags need an environment from either.
void applyEnvironmentOverrides(const SceneOverrides& o, scene::Scene& scene) {
  if (!o.environment.empty()) {
    if (!scene.environment) scene.environment = scene::Environment{.methodStated = false, .samplesStated = false};
    scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(o.environment));
  }
  // A script renders every scene of a folder seeds apart, whether or not it has an environment.
  if (o.seed && !scene.environment) scene.warnings.push_back(seedChangesNothing("--seed " + std::to_string(*o.seed)));
  const bool anyEnvironmentFlag = o.environmentIntensity || o.environmentRotation || !o.ibl.empty() || o.iblSamples ||
                                  !o.occlusion.empty() || (o.seed && scene.environment);
  if (!anyEnvironmentFlag) return;
  if (!scene.environment)
    throw std::invalid_argument(
        "--env-intensity, --env-rotation, --ibl, --ibl-samples and --occlusion need an environment: give --env FILE "
        "or an \"environment\" block in the scene");
  scene::Environment& e = *scene.environment;
  if (o.environmentIntensity) e.intensity = *o.environmentIntensity;
  if (o.environmentRotation) e.rotationDegrees = *o.environmentRotation;
  if (!o.ibl.empty())
    e.method = o.ibl == "sampled"    ? scene::IblMethod::Sampled
               : o.ibl == "filtered" ? scene::IblMethod::Filtered
                                     : scene::IblMethod::Prefiltered;
  if (o.iblSamples) {
    e.samples = *o.iblSamples;
    e.samplesStated = true;
  }
  if (!o.occlusion.empty()) e.occlusion = o.occlusion == "on";
  if (!o.ibl.empty() || !o.occlusion.empty()) e.methodStated = true;
  if (o.seed) e.seed = *o.seed;
}

}  // namespace

void applySceneOverrides(const SceneOverrides& o, scene::Scene& scene) {
  if (!o.size.empty()) applyImageSize(o.size, scene);
  if (!o.eye.empty()) scene.camera.eye = vector3(o.eye);
  if (!o.target.empty()) scene.camera.target = vector3(o.target);
  if (!o.up.empty()) scene.camera.up = vector3(o.up);
  if (o.fov) scene.camera.verticalFovDegrees = *o.fov;
  if (const char* problem = scene::cameraProblem(scene.camera))
    throw std::invalid_argument("--eye, --target, --up: the camera cannot render: " + std::string(problem));
  if (!o.subdivision.empty()) scene::overrideSubdivision(scene, o.subdivision, "--subdivision");
  if (!o.method.empty()) applyMethod(o.method, scene);
  if (o.tessLevel) scene.render.tessellationRate = *o.tessLevel;
  if (o.spp) {
    if (!scene::isSquare(*o.spp))
      throw std::invalid_argument("--spp " + std::to_string(*o.spp) + ": " + scene::kSamplesPerPixelRule);
    scene.render.samplesPerPixel = *o.spp;
    scene.render.sampling = scene::Sampling::OnePass;
  }
  if (o.bounces) {
    scene.render.bounces = *o.bounces;
    scene.render.bouncesStated = true;
  }
  if (o.diffuseBounces) scene.render.diffuseBounces = *o.diffuseBounces;
  if (o.glossyBounces) scene.render.glossyBounces = *o.glossyBounces;
  if (o.transmissionBounces) scene.render.transmissionBounces = *o.transmissionBounces;
  applyEnvironmentOverrides(o, scene);
  if (scene::bouncesContradictEnvironment(scene.render, scene.environment)) {
    // Named by the flags that set them, so a command without --bounces (preview) names what it has.
    const std::string bounces = std::to_string(scene.render.bounces);
    const std::string given = (o.bounces ? "--bounces " + bounces : "the scene's render.bounces " + bounces) +
                              (o.ibl.empty() ? "" : " with --ibl " + o.ibl) +
                              (o.occlusion.empty() ? "" : " with --occlusion " + o.occlusion);
    throw std::invalid_argument(given + ": " + scene::kBouncesNeedOcclusionRule);
  }
  applyEnergyCompensation(o.energyCompensation, scene);
}

void applyEnergyCompensation(const std::string& onOrOff, scene::Scene& scene) {
  if (onOrOff.empty()) return;
  for (materials::Material& material : scene.materials) material.energyCompensation = onOrOff == "on";
}

void addEnergyCompensationOption(CLI::App& command, std::string& onOrOff) {
  command
      .add_option("--energy-compensation", onOrOff,
                  "Multiple-scattering compensation of every material's specular lobe (default: each material's "
                  "energy_compensation, off)")
      ->check(CLI::IsMember({"on", "off"}));
}

std::string seedChangesNothing(const std::string& given) {
  return given + ": changes nothing here: without an environment the scene's random numbers are fixed";
}

std::string describeEnvironment(const scene::Environment& e) {
  const std::string source = e.map->source.empty() ? "constant colour" : e.map->source.string();
  std::string text =
      "environment: " + source + " (" + std::to_string(e.map->width) + "x" + std::to_string(e.map->height) + "), " +
      (e.method == scene::IblMethod::Prefiltered
           ? std::string("prefiltered")
           : std::string(e.method == scene::IblMethod::Sampled ? "sampled, " : "filtered, ") +
                 std::to_string(e.samples) + " pairs per camera sample, occlusion " + (e.occlusion ? "on" : "off"));
  return text;
}

void addEnvironmentOptions(CLI::App& command, SceneOverrides& o) {
  command.add_option("--env", o.environment, "Environment map (.exr or .hdr, equirectangular 2:1) lighting the scene")
      ->check(CLI::ExistingFile);
  command.add_option("--env-intensity", o.environmentIntensity, "Environment radiance scale")
      ->check(CLI::Range(0.0, 1e30));
  command.add_option("--env-rotation", o.environmentRotation, "Environment rotation about +y, in degrees");
}

void addSceneOverrideOptions(CLI::App& command, SceneOverrides& o) {
  command.add_option("--size", o.size, "Image size WIDTHxHEIGHT");
  auto triple = [&](const char* name, std::vector<double>& v, const char* help) {
    command.add_option(name, v, help)->delimiter(',')->expected(3)->check(CLI::Number);
  };
  triple("--eye", o.eye, "Camera position x,y,z");
  triple("--target", o.target, "Point the camera looks at x,y,z");
  triple("--up", o.up, "Camera up vector x,y,z");
  command.add_option("--fov", o.fov, "Vertical field of view in degrees")->check(CLI::Range(1e-3, 179.0));
  command.add_option(
      "--subdivision", o.subdivision,
      "Subdivision of every object, whatever the file chose: catmull-clark, or none (the polygons as authored); "
      "by default OBJ cages are subdivided and glTF meshes are not");
  command.add_option("--method", o.method, "Ray casting: exact limit surface, or tessellated")
      ->check(CLI::IsMember({"exact", "tess"}));
  command.add_option("--tess-level", o.tessLevel, "Dicing rate k (k x k per patch) for --method tess")
      ->check(CLI::Range(1, 256));
  command.add_option("--spp", o.spp, "Samples per pixel in one pass (a square number)")->check(CLI::Range(1, 4096));
  command
      .add_option("--bounces", o.bounces,
                  "Continuations of each camera sample's path (0: direct light only; above 0: --ibl sampled or "
                  "filtered with --occlusion on; default: chosen from the scene, 12 with Cycles' lobe limits where "
                  "a continuation can hit anything, else 0)")
      ->check(CLI::Range(0, scene::kMaxBounces));
  for (auto [flag, kind, value] : {std::tuple{"--diffuse-bounces", "diffuse", &o.diffuseBounces},
                                   std::tuple{"--glossy-bounces", "glossy", &o.glossyBounces},
                                   std::tuple{"--transmission-bounces", "transmission", &o.transmissionBounces}})
    command
        .add_option(flag, *value,
                    std::string("Continuations of the ") + kind +
                        " lobes a path may take besides --bounces (default: no limit of their own; Cycles': 4, 4, "
                        "12 for diffuse, glossy, transmission)")
        ->check(CLI::Range(0, scene::kMaxBounces));
  addEnvironmentOptions(command, o);
  command
      .add_option("--ibl", o.ibl,
                  "Image-based lighting: Monte Carlo with MIS, the prefiltered split sum, or BRDF samples read "
                  "from the map's mip chain (default: the scene's; where it says none, prefiltered, or sampled "
                  "with occlusion where paths run)")
      ->check(CLI::IsMember({"sampled", "prefiltered", "filtered"}));
  command
      .add_option("--ibl-samples", o.iblSamples,
                  "Sampled and filtered IBL: sample pairs per camera sample (--spp camera samples per pixel); "
                  "default 16, or 2 where facet chooses paths")
      ->check(CLI::Range(1, 16384));
  command.add_option("--occlusion", o.occlusion, "Sampled and filtered IBL: shadow rays towards the environment")
      ->check(CLI::IsMember({"on", "off"}));
  command
      .add_option("--seed", o.seed,
                  "The random numbers of the camera's samples, the environment's and the paths': renders with "
                  "different seeds are independent (default: the scene's environment.seed, 0; without an "
                  "environment they are fixed)")
      ->check(CLI::Range(0u, 2147483647u));
  addEnergyCompensationOption(command, o.energyCompensation);
}

}  // namespace facet::cli

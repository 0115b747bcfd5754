// The "render" and "environment" objects of facet's JSON scenes
// (docs/scene-format.md).
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "scenes/camera_rules.h"
#include "scenes/environment_map.h"
#include "scenes/json_field.h"
#include "scenes/json_overrides.h"
#include "scenes/scene_file.h"

namespace facet::scene::detail {

void readRender(const Field& f, RenderSettings& r) {
  f.object({"width", "height", "spp", "noise_threshold", "max_spp", "bounces", "diffuse_bounces", "glossy_bounces",
            "transmission_bounces", "method", "tess_level", "pixel_tolerance"});
  if (f.has("width")) r.width = f["width"].integer(1, 16384);
  if (f.has("height")) r.height = f["height"].integer(1, 16384);
  if (f.has("spp")) {
    if (f.has("noise_threshold") || f.has("max_spp"))
      f["spp"].fail(
          "give spp (one pass of that many samples) or noise_threshold and max_spp (adaptive rounds), "
          "not both");
    r.samplesPerPixel = f["spp"].integer(1, 4096);
    if (!isSquare(r.samplesPerPixel)) f["spp"].fail(kSamplesPerPixelRule);
    r.sampling = Sampling::OnePass;
  }
  if (f.has("noise_threshold")) {
    r.noiseThreshold = f["noise_threshold"].number(0.0, 1.0);
    if (!validNoiseThreshold(r.noiseThreshold)) f["noise_threshold"].fail(kNoiseThresholdRule);
    r.sampling = Sampling::Adaptive;
  }
  if (f.has("max_spp")) {
    r.maxSamplesPerPixel = f["max_spp"].integer(8, 65536);
    r.sampling = Sampling::Adaptive;
  }
  if (f.has("bounces")) {
    r.bounces = f["bounces"].integer(0, kMaxBounces);
    r.bouncesStated = true;
  }
  for (auto [key, limit] :
       {std::pair{"diffuse_bounces", &r.diffuseBounces}, std::pair{"glossy_bounces", &r.glossyBounces},
        std::pair{"transmission_bounces", &r.transmissionBounces}})
    if (f.has(key)) *limit = f[key].integer(0, kMaxBounces);
  if (f.has("method"))
    r.method = f["method"].choice<IntersectionMethod>(
        {{"exact", IntersectionMethod::Exact}, {"tess", IntersectionMethod::Tessellated}});
  if (f.has("tess_level")) r.tessellationRate = f["tess_level"].integer(1, 256);
  if (f.has("pixel_tolerance")) r.pixelTolerance = f["pixel_tolerance"].number(1e-3, 1e3);
}

Camera readCamera(const Field& f, Camera c) {
  f.object({"eye", "target", "up", "fov"});
  if (f.has("eye")) c.eye = f["eye"].vec3();
  if (f.has("target")) c.target = f["target"].vec3();
  if (f.has("up")) c.up = f["up"].direction();
  if (f.has("fov")) c.verticalFovDegrees = f["fov"].number(kMinFovDegrees, kMaxFovDegrees);
  if (const char* problem = cameraProblem(c)) f.fail(problem);
  return c;
}

Environment readEnvironment(const Field& f, const std::filesystem::path& sceneFile,
                            const std::optional<Environment>& start) {
  f.object({"file", "color", "intensity", "rotation", "method", "samples", "occlusion", "seed"});
  if (f.has("file") && f.has("color")) f.fail("give exactly one of file (an .exr or .hdr map) and color");
  if (!f.has("file") && !f.has("color") && !start) f.fail("give exactly one of file (an .exr or .hdr map) and color");
  Environment environment = start.value_or(Environment{.methodStated = false, .samplesStated = false});
  if (f.has("file")) {
    const Field file = f["file"];
    try {
      environment.map =
          std::make_shared<const EnvironmentMap>(loadEnvironmentMap(sceneFile.parent_path() / file.string()));
    } catch (const InputError& e) {
      file.fail(e.what());
    }
  } else if (f.has("color")) {
    const glm::dvec3 color = f["color"].vec3();
    if (const auto rule = radianceRule(color)) f["color"].fail(*rule);
    environment.map = std::make_shared<const EnvironmentMap>(constantEnvironment(color));
  }
  if (f.has("intensity")) {
    environment.intensity = f["intensity"].number(0.0);
    if (const auto rule = radianceRule(glm::dvec3(environment.intensity * environment.map->largestRadiance())))
      f["intensity"].fail("the brightest texel times the intensity " + *rule);
  }
  if (f.has("rotation")) environment.rotationDegrees = f["rotation"].number();
  if (f.has("method"))
    environment.method = f["method"].choice<IblMethod>(
        {{"sampled", IblMethod::Sampled}, {"prefiltered", IblMethod::Prefiltered}, {"filtered", IblMethod::Filtered}});
  if (f.has("samples")) {
    environment.samples = f["samples"].integer(1, 16384);
    environment.samplesStated = true;
  }
  if (f.has("occlusion")) environment.occlusion = f["occlusion"].boolean();
  if (f.has("method") || f.has("occlusion")) environment.methodStated = true;
  if (f.has("seed")) environment.seed = std::uint32_t(f["seed"].integer(0, std::numeric_limits<int>::max()));
  return environment;
}

}  // namespace facet::scene::detail

namespace facet::scene {

void applyModelOverrides(Scene& scene, const std::filesystem::path& modelFile,
                         std::span<const JsonOverride> overrides) {
  if (overrides.empty()) return;
  detail::json document = detail::json::object();
  for (const JsonOverride& o : overrides) {
    const std::string top = o.path.substr(0, o.path.find_first_of(".["));
    if (top != "render" && top != "camera" && top != "environment")
      throw std::invalid_argument("--set " + o.text() + ": a " + modelFile.extension().string() +
                                  " model takes --set for render, camera and environment fields only; give its "
                                  "objects' materials with --material");
    applyJsonOverride(document, o);
  }
  const std::string source = "--set";
  const detail::Field root(document, "", source);
  if (root.has("render")) detail::readRender(root["render"], scene.render);
  if (root.has("camera")) scene.camera = detail::readCamera(root["camera"], scene.camera);
  if (root.has("environment")) {
    const detail::Field environment = root["environment"];
    if (!scene.environment && environment.value().is_object() && !environment.has("file") && !environment.has("color"))
      environment.fail("the model has no environment (it has lights): give environment.file or environment.color");
    scene.environment = detail::readEnvironment(environment, modelFile, scene.environment);
  }
}

}  // namespace facet::scene

// The "render" and "environment" objects of facet's JSON scenes
// (docs/scene-format.md).
#include <memory>
#include <utility>

#include "scenes/environment_map.h"
#include "scenes/json_field.h"

namespace facet::scene::detail {

void readRender(const Field& f, RenderSettings& r) {
  f.object({"width", "height", "spp", "bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces", "method",
            "tess_level", "pixel_tolerance"});
  if (f.has("width")) r.width = f["width"].integer(1, 16384);
  if (f.has("height")) r.height = f["height"].integer(1, 16384);
  if (f.has("spp")) {
    r.samplesPerPixel = f["spp"].integer(1, 4096);
    if (!isSquare(r.samplesPerPixel)) f["spp"].fail(kSamplesPerPixelRule);
  }
  if (f.has("bounces")) r.bounces = f["bounces"].integer(0, kMaxBounces);
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

Environment readEnvironment(const Field& f, const std::filesystem::path& sceneFile) {
  f.object({"file", "color", "intensity", "rotation", "method", "samples", "occlusion"});
  if (f.has("file") == f.has("color")) f.fail("give exactly one of file (an .exr or .hdr map) and color");
  Environment environment;
  if (f.has("file")) {
    const Field file = f["file"];
    try {
      environment.map =
          std::make_shared<const EnvironmentMap>(loadEnvironmentMap(sceneFile.parent_path() / file.string()));
    } catch (const InputError& e) {
      file.fail(e.what());
    }
  } else {
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
  if (f.has("samples")) environment.samples = f["samples"].integer(1, 16384);
  if (f.has("occlusion")) environment.occlusion = f["occlusion"].boolean();
  return environment;
}

}  // namespace facet::scene::detail

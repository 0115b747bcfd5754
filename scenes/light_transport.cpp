#include "scenes/light_transport.h"

#include "materials/material.h"
#include "scenes/path_reach.h"
#include "scenes/scene_file.h"

namespace facet::scene {
namespace {

LightTransport asStated(const RenderSettings& r) {
  return {r.bounces, r.diffuseBounces, r.glossyBounces, r.transmissionBounces, false, 0, {}, {}};
}

std::string bounceLimits(const LightTransport& t) {
  return "paths: " + std::to_string(t.bounces) + " bounces (diffuse " + std::to_string(t.diffuseBounces) +
         ", glossy " + std::to_string(t.glossyBounces) + ", transmission " + std::to_string(t.transmissionBounces) +
         ")";
}

// After "environment sampled" where facet sampled it, else on its own.
std::string environmentPairsNote(const LightTransport& t) {
  if (t.environmentPairs == 0) return "";
  const std::string pairs = std::to_string(t.environmentPairs) + (t.environmentPairs == 1 ? " pair" : " pairs");
  return t.samplesEnvironment ? " (" + pairs + " per camera sample)"
                              : ", " + pairs + " of the environment per camera sample";
}

// Unless the scene stated otherwise, a limit of its own per lobe kind.
int chosenLimit(int stated, int chosen) { return stated >= 0 ? stated : chosen; }

// Glass with no path through it shows nothing behind it: said, never silent.
void warnOfDarkTransmission(const Scene& scene, const std::string& why, LightTransport& t) {
  for (const Object& object : scene.objects) {
    const materials::Material& material = scene.materials.at(std::size_t(object.material));
    if (!materials::isTransmissive(material)) continue;
    t.warnings.push_back("'" + material.name + "' transmits, but " + why +
                         ": no path passes through it and it shows nothing behind it");
    return;
  }
}

// A volume of glass must be closed for light to leave it as it entered
// (docs/rendering.md, "Transmission and absorption"): said, never silent.
void warnOfOpenVolumes(const Scene& scene, const SceneGeometry& geometry, LightTransport& t) {
  std::vector<std::string> open;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const materials::Material& material = scene.materials.at(std::size_t(scene.objects[i].material));
    if (materials::isTransmissive(material) && !material.thinWalled && !geometry.objects.at(i).enclosesSolid)
      open.push_back(scene.objects[i].name);
  }
  if (open.empty()) return;
  t.warnings.push_back("'" + open.front() + "'" +
                       (open.size() > 1 ? " (and " + std::to_string(open.size() - 1) + " more)" : "") +
                       " transmits into a volume, but its surface does not close around a solid (an open edge, a "
                       "hole or a face wound inward): light that enters may never leave; close it, wound outward, "
                       "or make its material thin-walled");
}

bool environmentCarriesPaths(const Scene& scene) { return pathsCountEnvironmentOnce(1, scene.environment); }

}  // namespace

LightTransport chooseLightTransport(const Scene& scene, const SceneGeometry& geometry) {
  LightTransport t = asStated(scene.render);
  warnOfOpenVolumes(scene, geometry, t);
  const bool methodStated = !scene.environment || scene.environment->methodStated;
  if (scene.render.bouncesStated) {
    if (t.bounces > 0 && !environmentCarriesPaths(scene) && !methodStated) {
      t.samplesEnvironment = true;
      t.note = "environment sampled: the stated bounces need its shadow rays";
    }
    if (t.bounces > 0 && (environmentCarriesPaths(scene) || t.samplesEnvironment))
      if (const PathReach reach = pathReach(scene, geometry); !reach.continues) {
        t = asStated(scene.render);
        t.bounces = 0;
        t.note = "paths: none cast: " + reach.why;
      }
    if (scene.render.bounces == 0) warnOfDarkTransmission(scene, "the bounces are stated 0", t);
    return t;
  }
  const PathReach reach = pathReach(scene, geometry);
  if (!reach.continues) {
    t.note = "direct light only: " + reach.why;
    return t;
  }
  if (!environmentCarriesPaths(scene) && methodStated) {
    t.note = "direct light only: the environment's stated method (prefiltered, or occlusion off) cannot light "
             "paths; give --ibl sampled to trace them (" + reach.why + ")";
    warnOfDarkTransmission(scene, "the environment's stated method cannot light paths", t);
    return t;
  }
  t.bounces = kChosenBounces;
  t.diffuseBounces = chosenLimit(scene.render.diffuseBounces, kChosenDiffuseBounces);
  t.glossyBounces = chosenLimit(scene.render.glossyBounces, kChosenGlossyBounces);
  t.transmissionBounces = chosenLimit(scene.render.transmissionBounces, kChosenTransmissionBounces);
  t.samplesEnvironment = !environmentCarriesPaths(scene);
  if (scene.environment && !scene.environment->samplesStated) t.environmentPairs = kChosenEnvironmentPairs;
  t.note = bounceLimits(t) + (t.samplesEnvironment ? ", environment sampled" : "") + environmentPairsNote(t) + ": " +
           reach.why;
  return t;
}

void leaveNothingToChoose(Scene& scene) {
  scene.render.sampling = Sampling::OnePass;
  scene.render.bouncesStated = true;
  if (!scene.environment || scene.environment->methodStated) return;
  if (scene.render.bounces > 0 && !environmentCarriesPaths(scene)) {
    LightTransport sampled = asStated(scene.render);
    sampled.samplesEnvironment = true;
    applyLightTransport(sampled, scene);
  }
  scene.environment->methodStated = true;
}

Scene loadStatedScene(const std::filesystem::path& path) {
  Scene scene = loadScene(path);
  leaveNothingToChoose(scene);
  return scene;
}

std::optional<std::uint32_t> estimateSeed(const Scene& scene) {
  const auto& e = scene.environment;
  if (!e || (e->method == IblMethod::Prefiltered && scene.render.bounces == 0)) return std::nullopt;
  return e->seed;
}

bool leavesLightTransportUnsaid(const Scene& scene) {
  return !scene.render.bouncesStated || (scene.environment && !scene.environment->methodStated);
}

Scene withLightTransport(Scene scene, const LightTransport& transport) {
  applyLightTransport(transport, scene);
  scene.render.bouncesStated = true;
  if (scene.environment) {
    scene.environment->methodStated = true;
    scene.environment->samplesStated = true;
  }
  return scene;
}

bool changesScene(const LightTransport& t, const Scene& scene) {
  const RenderSettings& r = scene.render;
  return t.bounces != r.bounces || t.diffuseBounces != r.diffuseBounces || t.glossyBounces != r.glossyBounces ||
         t.transmissionBounces != r.transmissionBounces || t.samplesEnvironment ||
         (t.environmentPairs > 0 && t.environmentPairs != scene.environment->samples);
}

void applyLightTransport(const LightTransport& t, Scene& scene) {
  scene.render.bounces = t.bounces;
  scene.render.diffuseBounces = t.diffuseBounces;
  scene.render.glossyBounces = t.glossyBounces;
  scene.render.transmissionBounces = t.transmissionBounces;
  if (t.samplesEnvironment) {
    scene.environment->method = IblMethod::Sampled;
    scene.environment->occlusion = true;
  }
  if (t.environmentPairs > 0) scene.environment->samples = t.environmentPairs;
}

}  // namespace facet::scene

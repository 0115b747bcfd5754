#include "analysis/peers/cycles_peer.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "analysis/timing.h"
#include "engine/image/child_process.h"
#include "engine/image/exr_file.h"
#include "rules/rules.h"

namespace facet::peers {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// What Blender may take for one section's renders before it is ended: far
// beyond the longest the bench asks for (BENCHMARKS.md).
constexpr double kBlenderTimeLimit = 4 * 3600;

bool isExecutable(const fs::path& path) { return fs::is_regular_file(path) && access(path.c_str(), X_OK) == 0; }

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

json triple(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

[[noreturn]] void noCounterpart(const materials::Material& m, const std::string& why) {
  throw std::invalid_argument("cycles: material '" + m.name + "' has no counterpart in cycles_scene.py: " + why);
}

// The material in the script's terms. Each kind is the same BSDF on both
// sides only under the conditions checked here (docs/shading.md, "Blender's
// metallic Fresnel"; docs/rendering.md, "Transmission").
json cyclesMaterial(const materials::Material& m) {
  using namespace rules::f64;
  if (m.textures || m.emission != glm::dvec3(0) || m.anisotropy != 0 || m.clearcoat != 0 ||
      m.sheenColor != glm::dvec3(0) || m.iridescence != 0 || m.energyCompensation)
    noCounterpart(m,
                  "textures, emission, anisotropy, a coat, sheen, a thin film and energy compensation are not "
                  "described");
  if (m.distribution != D_GGX) noCounterpart(m, "Cycles' microfacets are GGX");
  const double roughness = std::sqrt(m.alpha);
  if (m.transmission > 0) {
    if (m.transmission != 1 || m.thinWalled) noCounterpart(m, "glass is a closed volume, transmission 1");
    if (m.alpha > 0 && m.geometry != G_SMITH_GGX) noCounterpart(m, "rough glass needs the separable Smith G");
    glm::dvec3 absorption(0);
    if (std::isfinite(m.attenuationDistance)) absorption = -glm::log(m.attenuationColor) / m.attenuationDistance;
    return {{"kind", "glass"}, {"ior", m.eta.x}, {"roughness", roughness}, {"absorption", triple(absorption)}};
  }
  if (m.fresnel == F_DIELECTRIC && m.eta.x == 1.0) return {{"kind", "diffuse"}, {"albedo", triple(m.diffuse)}};
  if (m.fresnel == F_BLENDER_METALLIC && m.geometry == G_SMITH_GGX && m.diffuse == glm::dvec3(0))
    return {{"kind", "metal"}, {"base", triple(m.f0)}, {"roughness", roughness}};
  noCounterpart(m,
                "a metal needs Blender's metallic Fresnel, the separable Smith G and no diffuse; a diffuse "
                "surface the dielectric Fresnel of index 1 (no specular)");
}

}  // namespace

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

unsigned cyclesThreads() {
  const char* lavapipe = std::getenv("LP_NUM_THREADS");
  return lavapipe && std::atoi(lavapipe) > 0 ? unsigned(std::atoi(lavapipe)) : std::thread::hardware_concurrency();
}

fs::path describeForCycles(const scene::Scene& scene, const fs::path& directory) {
  if (!scene.environment || !scene.environment->map)
    throw std::invalid_argument("cycles: the scene has no environment map");
  if (!scene.lights.empty()) throw std::invalid_argument("cycles: punctual lights are not described");
  if (scene.environment->rotationDegrees != kCyclesMapRotationDegrees)
    throw std::invalid_argument("cycles: the environment must be turned by 270 degrees to match Cycles' map");
  const scene::Camera& camera = scene.camera;
  const scene::RenderSettings& render = scene.render;
  const auto limit = [&](int kind) { return kind < 0 ? render.bounces : std::min(kind, render.bounces); };
  json description = {
      {"size", {render.width, render.height}},
      {"camera",
       {{"eye", triple(camera.eye)},
        {"target", triple(camera.target)},
        {"up", triple(camera.up)},
        {"fov", camera.verticalFovDegrees}}},
      {"environment",
       {{"file", fs::absolute(scene.environment->map->source).string()}, {"intensity", scene.environment->intensity}}},
      {"bounces",
       {{"total", render.bounces},
        {"diffuse", limit(render.diffuseBounces)},
        {"glossy", limit(render.glossyBounces)},
        {"transmission", limit(render.transmissionBounces)}}},
      {"objects", json::array()}};
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const scene::Object& object = scene.objects[i];
    const fs::path cage = directory / ("object" + std::to_string(i) + ".obj");
    writeObj(cage, object.cage);
    const bool subdivided = object.subdivision == scene::Subdivision::CatmullClark;
    description["objects"].push_back({{"cage", cage.string()},
                                      {"levels", subdivided ? kCyclesSubdivisionLevels : 0},
                                      {"material", cyclesMaterial(scene.materials.at(std::size_t(object.material)))}});
  }
  const fs::path path = directory / "scene.json";
  std::ofstream(path) << description.dump(2) << "\n";
  return path;
}

void renderInCycles(const fs::path& blender, const fs::path& script, const fs::path& description,
                    const CyclesRenders& renders, const fs::path& directory) {
  std::string samples;
  for (int n : renders.samples) {
    if (!samples.empty()) samples += ',';
    samples += std::to_string(n);
  }
  const std::string threads = std::to_string(cyclesThreads());
  runChild({{blender.string(),
             "-b",
             "--factory-startup",
             "--python-exit-code",  // a script that raises fails the run, not only its log
             "1",
             "-t",
             threads,
             "--python",
             script.string(),
             "--",
             "--scene",
             description.string(),
             "--threads",
             threads,
             "--samples",
             samples,
             "--repeats",
             std::to_string(renders.repeats),
             "--converged",
             std::to_string(renders.converged),
             "--output",
             directory.string()},
            directory / "blender.log",
            kBlenderTimeLimit});
}

std::map<int, double> readCyclesTimes(const fs::path& csv, const std::vector<int>& samples) {
  std::ifstream in(csv);
  std::map<int, std::vector<double>> runs;
  std::string line;
  std::getline(in, line);  // header
  for (int samples; std::getline(in, line);)
    if (double seconds; std::sscanf(line.c_str(), "%d,%lf", &samples, &seconds) == 2) runs[samples].push_back(seconds);
  std::map<int, double> medians;
  for (const auto& [count, seconds] : runs) medians[count] = analysis::median(seconds);
  for (int count : samples)
    if (!medians.count(count))
      throw std::runtime_error(csv.string() + ": no time for Cycles' render at " + std::to_string(count) +
                               " samples; see blender.log beside it");
  return medians;
}

Image readCyclesImage(const fs::path& exr, const Image& reference) {
  const Image written = readExr(exr);
  if (written.width != reference.width || written.height != reference.height)
    throw std::runtime_error(exr.string() + ": Cycles' image is " + std::to_string(written.width) + " x " +
                             std::to_string(written.height) + ", facet rendered " + std::to_string(reference.width) +
                             " x " + std::to_string(reference.height));
  const auto broken = std::count_if(written.beauty.begin(), written.beauty.end(), [](const glm::vec4& p) {
    return !std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b);
  });
  if (broken > 0)
    throw std::runtime_error(exr.string() + ": " + std::to_string(broken) +
                             " of Cycles' pixels are not finite (NaN or infinite): its render failed, and is not "
                             "measured; see blender.log beside it");
  Image image = reference;
  image.beauty = written.beauty;
  return image;
}

}  // namespace facet::peers

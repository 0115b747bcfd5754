#include "engine/render_record.h"

#include <facet/version.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "engine/camera/camera.h"
#include "engine/ibl/prefilter_cache_format.h"
#include "scenes/light_transport.h"

namespace facet {
namespace {

ExrCamera exrCamera(const scene::Camera& camera, int width, int height) {
  const rules::f64::CameraFrame f = camera::cameraFrame(camera, width, height);
  return {f.eye, f.right, f.up, f.forward, f.tanHalfFovY, f.aspect};
}

ExrNames exrNames(const scene::Scene& scene) {
  ExrNames names;
  std::uint32_t faces = 0;
  for (const scene::Object& o : scene.objects) {
    names.objects.push_back(o.name);
    names.firstFace.push_back(faces);
    names.materialOf.push_back(std::uint32_t(o.material));
    faces += std::uint32_t(o.cage.faceCount());
  }
  for (const materials::Material& m : scene.materials) names.materials.push_back(m.name);
  return names;
}

// What decides a picture's pixels apart from the backend and the seed.
std::string pictureText(const scene::Scene& scene) {
  std::ostringstream text;
  text << std::hexfloat;
  if (!scene.source.empty()) {
    std::ifstream file(scene.source, std::ios::binary);
    text << file.rdbuf() << '\n';
  }
  const scene::RenderSettings& r = scene.render;
  text << r.width << ' ' << r.height << ' ' << r.samplesPerPixel << ' ' << int(r.method) << ' ' << r.pixelTolerance
       << ' ' << r.tessellationRate.value_or(-1) << ' ' << r.exactTolerance.value_or(-1) << '\n';
  if (r.sampling != scene::Sampling::OnePass)
    text << "sampling " << int(r.sampling) << ' ' << r.noiseThreshold << ' ' << r.maxSamplesPerPixel << '\n';
  if (r.bounces > 0) text << "bounces " << r.bounces << '\n';  // only above 0: a render without paths keeps its digest
  if (scene::limitsLobes(r))
    text << "lobes " << r.diffuseBounces << ' ' << r.glossyBounces << ' ' << r.transmissionBounces << '\n';
  const scene::Camera& c = scene.camera;
  for (const glm::dvec3& v : {c.eye, c.target, c.up}) text << v.x << ' ' << v.y << ' ' << v.z << ' ';
  text << c.verticalFovDegrees << '\n';
  for (const scene::Object& o : scene.objects)
    text << int(o.subdivision) << ' ' << scene.materials[std::size_t(o.material)].energyCompensation << ' ';
  if (const auto& e = scene.environment)
    text << '\n'
         << e->map->source << ' ' << e->intensity << ' ' << e->rotationDegrees << ' ' << int(e->method) << ' '
         << e->samples << ' ' << e->occlusion;
  return text.str();
}

std::string fnv1aHex(const std::string& text) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(ibl::cache_format::fnv1a(text.data(), text.size())));
  return hex;
}

// settingsDigest of the scene whose pictureText is `picture`.
std::string settingsDigestOf(const std::string& picture, const scene::Scene& scene, const std::string& backend) {
  std::string text = backend + '\n' + picture;
  if (scene.environment) text += ' ' + std::to_string(scene.environment->seed);
  return fnv1aHex(text);
}

}  // namespace

std::string settingsDigest(const scene::Scene& scene, const std::string& backend) {
  return settingsDigestOf(pictureText(scene), scene, backend);
}

std::string renderSettingsText(const scene::Scene& scene, const std::string& backend) {
  const scene::RenderSettings& r = scene.render;
  const auto orAuto = [](const auto& value) { return value ? std::to_string(*value) : std::string("auto"); };
  std::ostringstream text;
  text << "backend=" << backend << " size=" << r.width << 'x' << r.height;
  if (r.sampling == scene::Sampling::OnePass)
    text << " spp=" << r.samplesPerPixel;
  else
    text << " sampling=" << (r.sampling == scene::Sampling::Adaptive ? "adaptive" : "chosen")
         << " noiseThreshold=" << r.noiseThreshold << " maxSpp=" << r.maxSamplesPerPixel;
  text << " method=" << (r.method == scene::IntersectionMethod::Exact ? "exact" : "tess")
       << " pixelTolerance=" << r.pixelTolerance << " tessellationRate=" << orAuto(r.tessellationRate);
  if (r.bounces > 0) text << " bounces=" << r.bounces;
  if (scene::limitsLobes(r))
    text << " diffuseBounces=" << r.diffuseBounces << " glossyBounces=" << r.glossyBounces
         << " transmissionBounces=" << r.transmissionBounces;
  if (const auto& e = scene.environment) {
    const char* methods[] = {"sampled", "prefiltered", "filtered"};  // in IblMethod's order
    text << " ibl=" << methods[int(e->method)] << " iblSamples=" << e->samples
         << " iblOcclusion=" << (e->occlusion ? "on" : "off") << " iblSeed=" << e->seed;
  } else {
    text << " ibl=none";
  }
  const auto compensated = [](const materials::Material& m) { return m.energyCompensation; };
  if (std::any_of(scene.materials.begin(), scene.materials.end(), compensated)) text << " energyCompensation=on";
  return text.str();
}

ExrOptions describedExr(const scene::Scene& scene, const std::string& backend, const PixelRect& window,
                        const ExrLayers& layers, bool halfBeauty) {
  const int width = scene.render.width, height = scene.render.height;
  const std::string picture = pictureText(scene);  // the scene file read once for both digests
  ExrOptions exr;
  exr.placement = ExrPlacement{window, width, height, settingsDigestOf(picture, scene, backend)};
  exr.metadata = {
      exrCamera(scene.camera, width, height),
      {"facet " FACET_VERSION_STRING, renderSettingsText(scene, backend), fnv1aHex(picture), estimateSeed(scene)},
      exrNames(scene)};
  exr.layers = layers;
  exr.halfBeauty = halfBeauty;
  return exr;
}

}  // namespace facet

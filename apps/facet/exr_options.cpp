#include "exr_options.h"

#include <facet/version.h>

#include "engine/camera/camera.h"
#include "settings_digest.h"

namespace facet::cli {
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

}  // namespace

void addExrOptions(CLI::App& command, ExrCommandOptions& options) {
  command.add_option(
      "--aovs", options.aovs,
      "EXR layers: all, beauty, or a comma-separated list of: " + exrLayerNames() + " (the beauty is always written)");
  command.add_flag("--half", options.half, "Write the EXR's beauty as 16-bit half floats");
}

ExrLayers chosenExrLayers(const ExrCommandOptions& options) { return parseExrLayers(options.aovs, "--aovs"); }

ExrOptions exrOptions(const scene::Scene& scene, const std::string& backend, const PixelRect& window,
                      const ExrCommandOptions& options) {
  const int width = scene.render.width, height = scene.render.height;
  ExrOptions exr;
  exr.placement = ExrPlacement{window, width, height, settingsDigest(scene, backend)};
  exr.metadata = {exrCamera(scene.camera, width, height), "facet " FACET_VERSION_STRING,
                  renderSettingsText(scene, backend), exrNames(scene)};
  exr.layers = chosenExrLayers(options);
  exr.halfBeauty = options.half;
  return exr;
}

}  // namespace facet::cli

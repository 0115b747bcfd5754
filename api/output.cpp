// The CLI's writers behind the public API: the same EXR description
// (engine/render_record.h) and the same preview (engine/image/preview.h).
#include "facet/output.h"

#include <string>

#include "api/errors.h"
#include "api/image_planes.h"
#include "api/render_settings.h"
#include "api/scene_data.h"
#include "engine/image/exr_file.h"
#include "engine/image/image_io.h"
#include "engine/render_record.h"
#include "scenes/light_transport.h"
#include "scenes/sampling_choice.h"
#include "scenes/scene_geometry.h"

namespace facet::v0 {
namespace {

// The EXR of `image`, rendered from `scene` with `settings`, its path and
// settings checked before anything is written; `flag` names the path in an
// error.
OutputFile exrOutput(const std::string& flag, const std::string& path, const facet::Image& image,
                     const RenderResult& result, const Scene& scene, const RenderSettings& settings,
                     const ExrSettings& exr) {
  checkOutputPath(flag, path);
  checkOutputExtension(flag, path, ".exr");
  checkNotAnInput(flag, path, scene.data().inputs);
  scene::Scene rendered = withSettings(scene, settings);
  // The file records what the render chose, as `facet render` records it:
  // the choice follows from the scene and the settings alone, and changes
  // the record only where the render's bounces differ or its paths sample
  // an unsaid environment; the sampling follows from the light transport.
  if (result.bounces != rendered.render.bounces || (result.bounces > 0 && scene::leavesLightTransportUnsaid(rendered)))
    rendered =
        scene::withLightTransport(rendered, scene::chooseLightTransport(rendered, scene::buildGeometry(rendered)));
  scene::chooseSampling(rendered);
  if (image.width != rendered.render.width || image.height != rendered.render.height)
    throw Error(ErrorKind::BadInput, "image: " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                                         " is not the " + std::to_string(rendered.render.width) + " x " +
                                         std::to_string(rendered.render.height) + " the scene and settings render");
  const std::string backend = settings.backend == Backend::Cpu ? "cpu" : "gpu";
  return exrFile(path, image,
                 describedExr(rendered, backend, {0, 0, image.width, image.height},
                              parseExrLayers(exr.layers, "layers"), exr.halfBeauty));
}

// The PNG preview of `image`, its path and settings checked.
OutputFile pngOutput(const std::string& flag, const std::string& path, const facet::Image& image,
                     const PngSettings& png) {
  checkOutputPath(flag, path);
  checkOutputExtension(flag, path, ".png");
  if (!validExposure(png.exposure)) throw Error(ErrorKind::BadInput, std::string("exposure: ") + kExposureRule);
  PreviewOptions preview;
  preview.exposure = float(png.exposure);
  preview.curve = png.toneCurve == ToneCurve::Aces    ? facet::ToneCurve::Aces
                  : png.toneCurve == ToneCurve::Clamp ? facet::ToneCurve::Clamp
                                                      : facet::ToneCurve::PbrNeutral;
  if (png.background) {
    const glm::dvec3 colour(png.background->x, png.background->y, png.background->z);
    if (!validBackground(colour)) throw Error(ErrorKind::BadInput, std::string("background: ") + kBackgroundRule);
    preview.background = glm::vec3(colour);
  }
  preview.straightAlpha = png.straightAlpha;
  return pngFile(path, image, preview);
}

}  // namespace

void writeExr(const std::string& path, const RenderResult& result, const Scene& scene, const RenderSettings& settings,
              const ExrSettings& exr) {
  api::translateErrors([&] {
    const facet::Image image = engineImage(result.image);
    writeAllOrNothing({exrOutput("path", path, image, result, scene, settings, exr)});
  });
}

void writePng(const std::string& path, const Image& image, const PngSettings& png) {
  api::translateErrors([&] {
    const facet::Image pixels = engineImage(image);
    writeAllOrNothing({pngOutput("path", path, pixels, png)});
  });
}

void writePng(const std::string& path, const Image& image, const Scene& scene, const PngSettings& png) {
  api::translateErrors([&] {
    checkNotAnInput("path", path, scene.data().inputs);
    const facet::Image pixels = engineImage(image);
    writeAllOrNothing({pngOutput("path", path, pixels, png)});
  });
}

void writeExrAndPng(const std::string& exrPath, const std::string& pngPath, const RenderResult& result,
                    const Scene& scene, const RenderSettings& settings, const ExrSettings& exr,
                    const PngSettings& png) {
  api::translateErrors([&] {
    const facet::Image image = engineImage(result.image);
    const OutputFile exrOutputFile = exrOutput("exrPath", exrPath, image, result, scene, settings, exr);
    const OutputFile pngOutputFile = pngOutput("pngPath", pngPath, image, png);
    checkNotAnInput("pngPath", pngPath, scene.data().inputs);
    if (namesSameFile(exrPath, pngPath)) throw OutputError("pngPath '" + pngPath + "': names the same file as exrPath");
    writeAllOrNothing({exrOutputFile, pngOutputFile});
  });
}

}  // namespace facet::v0

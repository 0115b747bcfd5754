// The preview stage in Python: Renderer.preview returns a frame's pictures
// and sheet as numpy arrays, Renderer.write_preview writes what `facet
// preview` writes; their keywords are its flags'.
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "python/bindings.h"

namespace facet_python {
namespace {

// A (height, width, 4) uint8 array of 8-bit RGBA.
py::array rgbaArray(std::vector<std::uint8_t>&& rgba, int width, int height) {
  return ownedArray(std::move(rgba), {py::ssize_t(height), py::ssize_t(width), 4});
}

facet::PreviewSettings previewSettings(const std::vector<py::object>& materials, std::pair<int, int> size, int columns,
                                       bool ground, std::optional<facet::Environment> environment,
                                       double noiseThreshold, int maxSpp, OptReal timeLimit,
                                       std::optional<int> turntable, const std::string& turn,
                                       const std::string& backend, double exposure, const std::string& tonemap) {
  facet::PreviewSettings s;
  for (const py::object& m : materials) s.materials.push_back(fspath(m));
  std::tie(s.width, s.height) = size;
  s.columns = columns;
  s.ground = ground;
  s.environment = std::move(environment);
  s.noiseThreshold = noiseThreshold;
  s.maxSpp = maxSpp;
  s.timeLimit = timeLimit;
  s.turntable = turntable;
  s.turn =
      choice<facet::Turn>(turn, "turn", {{"model", facet::Turn::Model}, {"environment", facet::Turn::Environment}});
  s.backend = choice<facet::Backend>(backend, "backend", {{"gpu", facet::Backend::Gpu}, {"cpu", facet::Backend::Cpu}});
  s.exposure = exposure;
  s.toneCurve = choice<facet::ToneCurve>(tonemap, "tonemap",
                                         {{"pbr-neutral", facet::ToneCurve::PbrNeutral},
                                          {"aces", facet::ToneCurve::Aces},
                                          {"clamp", facet::ToneCurve::Clamp}});
  return s;
}

py::dict sheetDict(facet::PreviewSheet&& sheet) {
  py::list pictures;
  for (facet::PreviewPicture& p : sheet.pictures) {
    const int width = p.image.width, height = p.image.height;
    pictures.append(py::dict(py::arg("label") = p.label, py::arg("rgba") = rgbaArray(std::move(p.rgba), width, height),
                             py::arg("image") = imageDict(std::move(p.image)),
                             py::arg("adaptive") = adaptiveDict(p.sampling)));
  }
  return py::dict(py::arg("frame") = sheet.frame, py::arg("pictures") = pictures,
                  py::arg("sheet") = rgbaArray(std::move(sheet.rgba), sheet.width, sheet.height));
}

// The keywords both methods take after their own, in order: `facet preview`'s flags.
auto stageKeywords() {
  return std::make_tuple(
      py::arg("size") = std::pair<int, int>{256, 256}, py::arg("columns") = 0, py::arg("ground") = true,
      py::arg("environment") = py::none(), py::arg("noise_threshold") = 0.02, py::arg("max_spp") = 256,
      py::arg("time_limit") = py::none(), py::arg("turntable") = py::none(), py::arg("turn") = "model",
      py::arg("backend") = "gpu", py::arg("exposure") = 0.0, py::arg("tonemap") = "pbr-neutral");
}

}  // namespace

void bindPreview(py::class_<facet::Renderer>& renderer) {
  std::apply(
      [&](auto&&... keywords) {
        renderer.def(
            "preview",
            [](facet::Renderer& r, const py::object& model, const std::vector<py::object>& materials, int frame,
               std::pair<int, int> size, int columns, bool ground, std::optional<facet::Environment> environment,
               double noiseThreshold, int maxSpp, OptReal timeLimit, std::optional<int> turntable,
               const std::string& turn, const std::string& backend, double exposure, const std::string& tonemap) {
              const facet::Scene scene = sceneOf(model);
              const facet::PreviewSettings s =
                  previewSettings(materials, size, columns, ground, std::move(environment), noiseThreshold, maxSpp,
                                  timeLimit, turntable, turn, backend, exposure, tonemap);
              facet::PreviewSheet sheet = [&] {
                py::gil_scoped_release unlocked;
                return r.preview(scene, s, frame);
              }();
              return sheetDict(std::move(sheet));
            },
            py::arg("model"), py::arg("materials"), py::kw_only(), py::arg("frame") = 0, keywords...,
            "The preview stage (facet preview): each material on the model (a Scene or a file) over the ground, "
            "rendered to the noise threshold; returns frame's pictures (label, rgba, image, adaptive) and sheet");
        renderer.def(
            "write_preview",
            [](facet::Renderer& r, const py::object& model, const std::vector<py::object>& materials,
               const py::object& output, double fps, std::pair<int, int> size, int columns, bool ground,
               std::optional<facet::Environment> environment, double noiseThreshold, int maxSpp, OptReal timeLimit,
               std::optional<int> turntable, const std::string& turn, const std::string& backend, double exposure,
               const std::string& tonemap) {
              const facet::Scene scene = sceneOf(model);
              const facet::PreviewSettings s =
                  previewSettings(materials, size, columns, ground, std::move(environment), noiseThreshold, maxSpp,
                                  timeLimit, turntable, turn, backend, exposure, tonemap);
              const std::string path = fspath(output);
              py::gil_scoped_release unlocked;
              r.writePreview(scene, s, path, fps);
            },
            py::arg("model"), py::arg("materials"), py::arg("output"), py::kw_only(), py::arg("fps") = 24.0,
            keywords...,
            "Writes what facet preview writes: the sheet (.png), or with a turntable the movie (.mp4 or .gif, by "
            "ffmpeg on PATH)");
      },
      stageKeywords());
}

}  // namespace facet_python

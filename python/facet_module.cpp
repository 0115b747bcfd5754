// The Python module `facet`: facet's public API (include/facet/) for scripts
// and notebooks. Images come back as numpy arrays that own the render's
// planes (no copy); every facet::Error becomes facet.Error with its message.
#include <string>
#include <utility>
#include <vector>

#include "python/bindings.h"

namespace {

using namespace facet_python;

facet::RenderSettings settingsOf(std::optional<std::pair<int, int>> size, const std::string& backend,
                                 std::optional<std::string> method, std::optional<int> spp,
                                 std::optional<int> tessLevel, std::optional<int> bounces) {
  facet::RenderSettings s;
  s.backend = choice<facet::Backend>(backend, "backend", {{"gpu", facet::Backend::Gpu}, {"cpu", facet::Backend::Cpu}});
  if (size) {
    s.width = size->first;
    s.height = size->second;
  }
  if (method)
    s.method = choice<facet::Method>(*method, "method",
                                     {{"exact", facet::Method::Exact}, {"tess", facet::Method::Tessellated}});
  s.spp = spp;
  s.tessLevel = tessLevel;
  s.bounces = bounces;
  return s;
}

// What `facet render` writes, named as its flags are: -o (exr), --png,
// --aovs, --half, --exposure, --tonemap, --background, --alpha.
struct Outputs {
  std::optional<std::string> exr, png;
  std::string aovs = "all";
  bool half = false;
  double exposure = 0;
  std::string tonemap = "pbr-neutral";
  std::optional<facet::Vec3> background;
  bool alpha = false;
};

// Both files as a set, as the command line writes them: neither is
// replaced unless both can be.
void writeOutputs(const Outputs& o, const facet::RenderResult& result, const facet::Scene& scene,
                  const facet::RenderSettings& settings) {
  const facet::ExrSettings exr{o.aovs, o.half};
  if (!o.png) {
    if (o.exr) facet::writeExr(*o.exr, result, scene, settings, exr);
    return;
  }
  const facet::ToneCurve curve = choice<facet::ToneCurve>(o.tonemap, "tonemap",
                                                          {{"pbr-neutral", facet::ToneCurve::PbrNeutral},
                                                           {"aces", facet::ToneCurve::Aces},
                                                           {"clamp", facet::ToneCurve::Clamp}});
  const facet::PngSettings png{o.exposure, curve, o.background, o.alpha};
  if (o.exr)
    facet::writeExrAndPng(*o.exr, *o.png, result, scene, settings, exr, png);
  else
    facet::writePng(*o.png, result.image, scene, png);
}

py::dict renderDict(facet::Renderer& renderer, const py::object& sceneOrPath, const facet::RenderSettings& settings,
                    const Outputs& outputs) {
  const facet::Scene scene = sceneOf(sceneOrPath);
  facet::RenderResult result = [&] {
    py::gil_scoped_release unlocked;
    facet::RenderResult rendered = renderer.render(scene, settings);
    writeOutputs(outputs, rendered, scene, settings);
    return rendered;
  }();
  py::dict out = imageDict(std::move(result.image));
  out["bounces"] = result.bounces;
  out["light_transport"] = result.lightTransport;
  // The sampling as `facet render --json` reports it: `spp`, or `adaptive`; `sampling` where chosen.
  const facet::SamplingReport& s = result.sampling;
  if (s.spp > 0)
    out["spp"] = s.spp;
  else
    out["adaptive"] = adaptiveDict(s);
  if (!s.why.empty()) out["sampling"] = s.why;
  // As `facet render --json` reports it: only paths of bounces above 0 have it.
  if (result.raysPerBounce.empty()) return out;
  py::list bounces;
  for (const facet::BounceRays& rays : result.raysPerBounce)
    bounces.append(
        py::dict(py::arg("rays") = rays.rays, py::arg("hits") = rays.hits, py::arg("shadow_rays") = rays.shadowRays));
  out["rays_per_bounce"] = bounces;
  return out;
}

// Renderer.watch: the callbacks run with the interpreter held; an exception
// one raises stops the watch and is raised again when it returns.
void watchScene(facet::Renderer& renderer, const std::string& scene, const py::function& callback,
                const facet::WatchSettings& settings, const py::object& onBadInput) {
  std::optional<py::error_already_set> raised;
  const auto onPass = [&](const facet::WatchPass& pass) {
    py::gil_scoped_acquire held;
    try {
      facet::Image image = pass.image;
      const py::object goOn =
          callback(py::dict(py::arg("picture") = pass.picture, py::arg("passes") = pass.passes,
                            py::arg("spp") = pass.spp, py::arg("image") = imageDict(std::move(image))));
      return goOn.is_none() || goOn.cast<bool>();
    } catch (py::error_already_set& e) {
      raised = std::move(e);
      return false;
    }
  };
  std::function<bool(const facet::Error&)> badInput;
  if (!onBadInput.is_none())
    badInput = [&](const facet::Error& e) {
      py::gil_scoped_acquire held;
      try {
        const py::object goOn = onBadInput(e.what());
        return goOn.is_none() || goOn.cast<bool>();
      } catch (py::error_already_set& error) {
        raised = std::move(error);
        return false;
      }
    };
  {
    py::gil_scoped_release unlocked;
    renderer.watch(scene, onPass, settings, badInput);
  }
  if (raised) throw std::move(*raised);
}

// The scene's entry of `facet parity --json`, with its verdict, whether it
// passed, the renders per backend and the table at the top.
py::dict parityDict(facet::Renderer& renderer, const py::object& sceneOrPath, const facet::RenderSettings& settings,
                    const facet::ParityOptions& options) {
  const facet::Scene scene = sceneOf(sceneOrPath);
  const facet::ParityReport r = [&] {
    py::gil_scoped_release unlocked;
    return renderer.parity(scene, settings, options);
  }();
  py::dict out = py::module_::import("json").attr("loads")(r.json);
  out["verdict"] = r.verdict;
  out["pass"] = r.pass;
  out["renders"] = r.renders;
  out["summary"] = r.summary;
  return out;
}

py::dict brdfDict(const facet::Material& material, const py::object& l, const py::object& v) {
  // Broadcast l against v, as numpy would, so one direction may meet many.
  const py::sequence both = py::module_::import("numpy").attr("broadcast_arrays")(directions(l.cast<Doubles>(), "l"),
                                                                                  directions(v.cast<Doubles>(), "v"));
  const Doubles ls = Doubles::ensure(both[0]), vs = Doubles::ensure(both[1]);
  const std::vector<facet::BrdfValue> values = facet::evaluateBrdf(material, vectors(ls), vectors(vs));
  std::vector<py::ssize_t> shape(ls.shape(), ls.shape() + ls.ndim() - 1);
  std::vector<py::ssize_t> rgbShape = shape;
  rgbShape.push_back(3);
  std::vector<double> f, specular, diffuse, F, D, G;
  const auto push = [](std::vector<double>& out, const Vec3& c) { out.insert(out.end(), {c.x, c.y, c.z}); };
  for (const facet::BrdfValue& b : values) {
    push(f, b.f);
    push(specular, b.specular);
    push(diffuse, b.diffuse);
    push(F, b.F);
    D.push_back(b.D);
    G.push_back(b.G);
  }
  return py::dict(py::arg("f") = ownedArray(std::move(f), rgbShape),
                  py::arg("specular") = ownedArray(std::move(specular), rgbShape),
                  py::arg("diffuse") = ownedArray(std::move(diffuse), rgbShape),
                  py::arg("F") = ownedArray(std::move(F), rgbShape), py::arg("D") = ownedArray(std::move(D), shape),
                  py::arg("G") = ownedArray(std::move(G), shape));
}

// facet.Renderer: render, watch, parity and the preview stage on one device.
void bindRenderer(py::module_& m) {
  py::class_<facet::Renderer> renderer(m, "Renderer", "Keeps the GPU device and its compiled kernels between renders");
  bindPreview(renderer);
  renderer.def(py::init<const std::string&>(), py::arg("adapter") = "")
      .def(
          "render",
          [](facet::Renderer& r, const py::object& scene, std::optional<std::pair<int, int>> size,
             const std::string& backend, OptText method, std::optional<int> spp, std::optional<int> tessLevel,
             std::optional<int> bounces, OptText exr, OptText png, const std::string& aovs, bool half, double exposure,
             const std::string& tonemap, OptVec background, bool alpha) {
            return renderDict(r, scene, settingsOf(size, backend, method, spp, tessLevel, bounces),
                              {exr, png, aovs, half, exposure, tonemap, background, alpha});
          },
          py::arg("scene"), py::kw_only(), py::arg("size") = py::none(), py::arg("backend") = "gpu",
          py::arg("method") = py::none(), py::arg("spp") = py::none(), py::arg("tess_level") = py::none(),
          py::arg("bounces") = py::none(), py::arg("exr") = py::none(), py::arg("png") = py::none(),
          py::arg("aovs") = "all", py::arg("half") = false, py::arg("exposure") = 0.0,
          py::arg("tonemap") = "pbr-neutral", py::arg("background") = py::none(), py::arg("alpha") = false,
          "As facet.render, with this renderer's device and kernels kept between calls")
      .def(
          "watch",
          [](facet::Renderer& r, const py::object& scene, const py::function& callback, int passes, int changes,
             std::optional<std::pair<int, int>> size, const std::string& backend, OptText method,
             std::optional<int> spp, std::optional<int> tessLevel, std::optional<int> bounces,
             const std::string& variant, const py::object& onBadInput) {
            watchScene(r, fspath(scene), callback,
                       {settingsOf(size, backend, method, spp, tessLevel, bounces), passes, changes, variant},
                       onBadInput);
          },
          py::arg("scene"), py::arg("callback"), py::kw_only(), py::arg("passes") = 16, py::arg("changes") = 0,
          py::arg("size") = py::none(), py::arg("backend") = "gpu", py::arg("method") = py::none(),
          py::arg("spp") = py::none(), py::arg("tess_level") = py::none(), py::arg("bounces") = py::none(),
          py::arg("variant") = "", py::arg("on_bad_input") = py::none(),
          "Watches a scene file as facet render --watch: callback({picture, passes, spp, image}) after each pass of "
          "each picture, False to stop; changes: return after that many (0: until stopped); variant: a glTF "
          "file's material variant, as --variant; on_bad_input(error) for a later load refused, which otherwise "
          "ends the watch")
      .def(
          "parity",
          [](facet::Renderer& r, const py::object& scene, std::optional<std::pair<int, int>> size, OptText method,
             int renders, const std::vector<std::string>& tolerances, std::size_t minCoverage) {
            return parityDict(r, scene, settingsOf(size, "gpu", method, std::nullopt, std::nullopt, std::nullopt),
                              {renders, tolerances, minCoverage});
          },
          py::arg("scene"), py::kw_only(), py::arg("size") = py::none(), py::arg("method") = py::none(),
          py::arg("renders") = 16, py::arg("tolerances") = std::vector<std::string>{}, py::arg("min_coverage") = 16,
          "As facet.parity, with this renderer's device and kernels");
}

}  // namespace

namespace facet_python {

py::dict imageDict(facet::Image&& image) {
  py::dict out;
  const py::ssize_t h = image.height, w = image.width;
  for (auto& [name, aov] : image.aovs) {
    std::vector<py::ssize_t> shape{h, w};
    if (aov.channels > 1) shape.push_back(aov.channels);
    out[py::str(name)] = ownedArray(std::move(aov.values), shape);
  }
  for (auto& [name, ids] : image.ids) out[py::str(name)] = ownedArray(std::move(ids), {h, w});
  return out;
}

py::dict adaptiveDict(const facet::SamplingReport& s) {
  return py::dict(py::arg("rounds") = s.rounds, py::arg("spp_mean") = s.sppMean, py::arg("spp_min") = s.sppMin,
                  py::arg("spp_max") = s.sppMax, py::arg("max_tile_error") = s.maxTileError,
                  py::arg("noise_threshold") = s.noiseThreshold, py::arg("stop") = s.stop);
}

}  // namespace facet_python

PYBIND11_MODULE(facet, m) {
  m.doc() = "facet: physically based materials on subdivision surfaces, rendered on the GPU and a CPU reference";
  m.attr("__version__") = facet::version();
  // facet.Error(message), a ValueError whose exit_code is the kind of failure
  // (the exit code `facet` gives it: 1 bad input, 2 output, 3 GPU, 4 internal).
  static py::exception<facet::Error> error(m, "Error", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const facet::Error& e) {
      py::object instance = py::handle(error.ptr())(e.what());
      instance.attr("exit_code") = e.exitCode();
      PyErr_SetObject(error.ptr(), instance.ptr());
    }
  });

  bindScenes(m);

  bindRenderer(m);

  m.def(
      "render",
      [](const py::object& scene, std::optional<std::pair<int, int>> size, const std::string& backend, OptText method,
         std::optional<int> spp, std::optional<int> tessLevel, std::optional<int> bounces, const std::string& adapter,
         OptText exr, OptText png, const std::string& aovs, bool half, double exposure, const std::string& tonemap,
         OptVec background, bool alpha) {
        facet::Renderer renderer(adapter);
        return renderDict(renderer, scene, settingsOf(size, backend, method, spp, tessLevel, bounces),
                          {exr, png, aovs, half, exposure, tonemap, background, alpha});
      },
      py::arg("scene"), py::kw_only(), py::arg("size") = py::none(), py::arg("backend") = "gpu",
      py::arg("method") = py::none(), py::arg("spp") = py::none(), py::arg("tess_level") = py::none(),
      py::arg("bounces") = py::none(), py::arg("adapter") = "", py::arg("exr") = py::none(),
      py::arg("png") = py::none(), py::arg("aovs") = "all", py::arg("half") = false, py::arg("exposure") = 0.0,
      py::arg("tonemap") = "pbr-neutral", py::arg("background") = py::none(), py::arg("alpha") = false,
      "Renders a Scene or a scene file; returns {aov name: numpy array (height, width[, channels])}, with "
      "rays_per_bounce when bounces > 0. exr and png write the files facet render writes (-o, --png), with its "
      "--aovs, --half, --exposure, --tonemap, --background and --alpha");
  m.def(
      "parity",
      [](const py::object& scene, std::optional<std::pair<int, int>> size, OptText method, const std::string& adapter,
         int renders, const std::vector<std::string>& tolerances, std::size_t minCoverage) {
        facet::Renderer renderer(adapter);
        return parityDict(renderer, scene, settingsOf(size, "gpu", method, std::nullopt, std::nullopt, std::nullopt),
                          {renders, tolerances, minCoverage});
      },
      py::arg("scene"), py::kw_only(), py::arg("size") = py::none(), py::arg("method") = py::none(),
      py::arg("adapter") = "", py::arg("renders") = 16, py::arg("tolerances") = std::vector<std::string>{},
      py::arg("min_coverage") = 16,
      "GPU against the CPU reference, AOV by AOV, as facet parity judges it (renders, tolerances and min_coverage "
      "as its --renders, --tolerance and --min-coverage); returns its --json entry of the scene, with verdict, "
      "pass, renders and summary");
  m.def(
      "brdf",
      [](const py::object& l, const py::object& v, std::optional<facet::Material> material, OptText d, OptText g,
         OptText f, OptText preset, OptReal alpha, OptReal roughness, OptVec f0, OptVec ior, OptVec eta, OptVec k,
         OptVec diffuse) {
        const facet::Material chosen =
            material.value_or(facet::Material{"", preset, d, g, f, alpha, roughness, f0, ior, eta, k, diffuse});
        return brdfDict(chosen, l, v);
      },
      py::arg("l"), py::arg("v"), py::kw_only(), py::arg("material") = py::none(), py::arg("distribution") = py::none(),
      py::arg("geometry") = py::none(), py::arg("fresnel") = py::none(), py::arg("preset") = py::none(),
      py::arg("alpha") = py::none(), py::arg("roughness") = py::none(), py::arg("f0") = py::none(),
      py::arg("ior") = py::none(), py::arg("eta") = py::none(), py::arg("k") = py::none(),
      py::arg("diffuse") = py::none(),
      "f, specular, diffuse, F (..., 3) and D, G (...) for directions l, v of shape (..., 3), n = +z");
  nameUnknownKeywords(m, error);
}

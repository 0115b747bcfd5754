// The Python module `facet`: facet's public API (include/facet/) for scripts
// and notebooks. Images come back as numpy arrays that own the render's
// planes (no copy); every facet::Error becomes facet.Error with its message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "facet/facet.h"

namespace py = pybind11;

// Vec3 from any sequence of 3 numbers (tuple, list, numpy array), to a tuple.
namespace pybind11::detail {
template <>
struct type_caster<facet::Vec3> {
  PYBIND11_TYPE_CASTER(facet::Vec3, const_name("tuple[float, float, float]"));
  bool load(handle source, bool) {
    if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
    const auto s = reinterpret_borrow<sequence>(source);
    if (s.size() != 3) return false;
    value = {s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()};
    return true;
  }
  static handle cast(const facet::Vec3& v, return_value_policy, handle) { return make_tuple(v.x, v.y, v.z).release(); }
};
}  // namespace pybind11::detail

namespace {

using facet::Vec3;
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A numpy view of `values`, which moves into a capsule the array owns.
template <class T>
py::array ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), owner);
}

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

facet::Scene sceneOf(const py::object& sceneOrPath) {
  if (py::isinstance<facet::Scene>(sceneOrPath)) return sceneOrPath.cast<facet::Scene>();
  const py::object path = py::module_::import("os").attr("fspath")(sceneOrPath);
  return facet::loadScene(path.cast<std::string>());
}

template <class T>
T choice(const std::string& name, const char* argument, std::initializer_list<std::pair<const char*, T>> options) {
  std::string list;
  for (const auto& [key, value] : options) {
    if (name == key) return value;
    list += (list.empty() ? "" : ", ") + std::string(key);
  }
  throw facet::Error(facet::ErrorKind::BadInput, std::string(argument) + " '" + name + "': expected one of: " + list);
}

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
  s.samplesPerPixel = spp;
  s.tessellationRate = tessLevel;
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

void writeOutputs(const Outputs& o, const facet::RenderResult& result, const facet::Scene& scene,
                  const facet::RenderSettings& settings) {
  if (o.exr) facet::writeExr(*o.exr, result, scene, settings, {o.aovs, o.half});
  if (!o.png) return;
  const facet::ToneCurve curve = choice<facet::ToneCurve>(o.tonemap, "tonemap",
                                                          {{"pbr-neutral", facet::ToneCurve::PbrNeutral},
                                                           {"aces", facet::ToneCurve::Aces},
                                                           {"clamp", facet::ToneCurve::Clamp}});
  facet::writePng(*o.png, result.image, {o.exposure, curve, o.background, o.alpha});
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
  // As `facet render --json` reports it: only paths of bounces above 0 have it.
  if (result.raysPerBounce.empty()) return out;
  py::list bounces;
  for (const facet::BounceRays& rays : result.raysPerBounce)
    bounces.append(
        py::dict(py::arg("rays") = rays.rays, py::arg("hits") = rays.hits, py::arg("shadow_rays") = rays.shadowRays));
  out["rays_per_bounce"] = bounces;
  return out;
}

py::dict parityDict(facet::Renderer& renderer, const py::object& sceneOrPath, const facet::RenderSettings& settings) {
  const facet::Scene scene = sceneOf(sceneOrPath);
  const facet::ParityReport r = [&] {
    py::gil_scoped_release unlocked;
    return renderer.parity(scene, settings);
  }();
  py::dict aovs;
  for (const facet::AovParity& a : r.aovs)
    aovs[py::str(a.name)] =
        py::dict(py::arg("max_relative") = a.maxRelative, py::arg("mean_relative") = a.meanRelative,
                 py::arg("tolerance") = a.tolerance, py::arg("share_over") = a.shareOver, py::arg("pass") = a.pass);
  return py::dict(py::arg("pass") = r.pass, py::arg("width") = r.width, py::arg("height") = r.height,
                  py::arg("covered") = r.covered, py::arg("coverage_mismatches") = r.coverageMismatches,
                  py::arg("coverage_pass") = r.coveragePass, py::arg("aovs") = aovs, py::arg("summary") = r.summary);
}

// Directions as an (..., 3) float64 array.
Doubles directions(const Doubles& a, const char* name) {
  if (a.ndim() < 1 || a.shape(a.ndim() - 1) != 3)
    throw facet::Error(facet::ErrorKind::BadInput, std::string(name) + ": expected an array of shape (..., 3)");
  return a;
}

std::vector<Vec3> vectors(const Doubles& a) {
  std::vector<Vec3> out(std::size_t(a.size() / 3));
  const double* p = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
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

// The ints of integer array `typed`, refusing a value outside int's range
// rather than wrapping it.
template <class T>
std::vector<int> checkedInts(const py::array_t<T, py::array::c_style | py::array::forcecast>& typed, const char* name) {
  std::vector<int> out;
  out.reserve(std::size_t(typed.size()));
  for (py::ssize_t i = 0; i < typed.size(); ++i) {
    const T value = typed.data()[i];
    if (!std::in_range<int>(value))
      throw facet::Error(facet::ErrorKind::BadInput, std::string(name) + "[" + std::to_string(i) + "]: " +
                                                         std::to_string(value) + " is out of range for an index");
    out.push_back(int(value));
  }
  return out;
}

// The ints of an index array: any integer dtype (a list of ints included).
// Floats and bools are refused, not truncated.
std::vector<int> indexArray(const py::handle& values, const char* name) {
  const py::array array = py::array::ensure(values);
  if (!array) throw facet::Error(facet::ErrorKind::BadInput, std::string(name) + ": expected an array of integers");
  if (array.size() == 0) return {};
  const char kind = array.dtype().kind();
  if (kind == 'u') return checkedInts<std::uint64_t>(array, name);
  if (kind == 'i') return checkedInts<std::int64_t>(array, name);
  throw facet::Error(facet::ErrorKind::BadInput, std::string(name) + ": expected integers, got an array of dtype " +
                                                     py::str(array.dtype()).cast<std::string>());
}

}  // namespace

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

  using OptVec = std::optional<Vec3>;
  using OptText = std::optional<std::string>;
  using OptReal = std::optional<double>;
  py::class_<facet::Material>(m, "Material", "A material as scene files write it (docs/shading.md)")
      .def(py::init([](const std::string& name, OptText preset, OptText d, OptText g, OptText f, OptReal alpha,
                       OptReal roughness, OptVec f0, OptVec ior, OptVec eta, OptVec k, OptVec diffuse,
                       bool energyCompensation, OptReal transmission, std::optional<bool> thinWalled, OptReal thickness,
                       OptVec attenuationColor, OptReal attenuationDistance) {
             facet::Material material{
                 name, preset, d, g, f, alpha, roughness, f0, ior, eta, k, diffuse, energyCompensation};
             material.transmission = transmission;
             material.thinWalled = thinWalled;
             material.thickness = thickness;
             material.attenuationColor = attenuationColor;
             material.attenuationDistance = attenuationDistance;
             return material;
           }),
           py::kw_only(), py::arg("name") = "", py::arg("preset") = py::none(), py::arg("distribution") = py::none(),
           py::arg("geometry") = py::none(), py::arg("fresnel") = py::none(), py::arg("alpha") = py::none(),
           py::arg("roughness") = py::none(), py::arg("f0") = py::none(), py::arg("ior") = py::none(),
           py::arg("eta") = py::none(), py::arg("k") = py::none(), py::arg("diffuse") = py::none(),
           py::arg("energy_compensation") = false, py::arg("transmission") = py::none(),
           py::arg("thin_walled") = py::none(), py::arg("thickness") = py::none(),
           py::arg("attenuation_color") = py::none(), py::arg("attenuation_distance") = py::none())
      .def_readwrite("name", &facet::Material::name)
      .def_readwrite("preset", &facet::Material::preset)
      .def_readwrite("distribution", &facet::Material::distribution)
      .def_readwrite("geometry", &facet::Material::geometry)
      .def_readwrite("fresnel", &facet::Material::fresnel)
      .def_readwrite("alpha", &facet::Material::alpha)
      .def_readwrite("roughness", &facet::Material::roughness)
      .def_readwrite("f0", &facet::Material::f0)
      .def_readwrite("ior", &facet::Material::ior)
      .def_readwrite("eta", &facet::Material::eta)
      .def_readwrite("k", &facet::Material::k)
      .def_readwrite("diffuse", &facet::Material::diffuse)
      .def_readwrite("energy_compensation", &facet::Material::energyCompensation)
      .def_readwrite("transmission", &facet::Material::transmission)
      .def_readwrite("thin_walled", &facet::Material::thinWalled)
      .def_readwrite("thickness", &facet::Material::thickness)
      .def_readwrite("attenuation_color", &facet::Material::attenuationColor)
      .def_readwrite("attenuation_distance", &facet::Material::attenuationDistance);

  py::class_<facet::Cage>(m, "Cage", "A Catmull-Clark control cage in world space, 0-based indices")
      .def(py::init([](const Doubles& positions, const py::object& counts, const py::object& indices,
                       const std::vector<std::tuple<int, int, double>>& creases) {
             facet::Cage cage{vectors(directions(positions, "positions")),
                              indexArray(counts, "face_vertex_counts"),
                              indexArray(indices, "face_vertex_indices"),
                              {}};
             for (const auto& [v0, v1, sharpness] : creases) cage.creases.push_back({v0, v1, sharpness});
             return cage;
           }),
           py::arg("positions"), py::arg("face_vertex_counts"), py::arg("face_vertex_indices"),
           py::arg("creases") = std::vector<std::tuple<int, int, double>>{});

  py::class_<facet::Object>(m, "Object", "A cage with the index of its material in the scene's materials")
      .def(py::init([](facet::Cage cage, int material, const std::string& name, bool subdivided) {
             return facet::Object{name, std::move(cage), material, subdivided};
           }),
           py::arg("cage"), py::kw_only(), py::arg("material") = 0, py::arg("name") = "", py::arg("subdivided") = true);

  py::class_<facet::Light>(m, "Light", "A punctual light; color is c_light")
      .def(py::init([](const std::string& type, Vec3 color, Vec3 position, Vec3 direction, double inner, double outer) {
             const auto kind = choice<facet::LightType>(type, "type",
                                                        {{"directional", facet::LightType::Directional},
                                                         {"point", facet::LightType::Point},
                                                         {"spot", facet::LightType::Spot}});
             return facet::Light{kind, color, position, direction, inner, outer};
           }),
           py::arg("type") = "directional", py::kw_only(), py::arg("color") = Vec3{1, 1, 1},
           py::arg("position") = Vec3{0, 0, 0}, py::arg("direction") = Vec3{0, -1, 0}, py::arg("inner_cone") = 30.0,
           py::arg("outer_cone") = 45.0);

  py::class_<facet::Camera>(m, "Camera", "A pinhole camera; fov is vertical, in degrees")
      .def(py::init([](Vec3 eye, Vec3 target, Vec3 up, double fov) {
             return facet::Camera{eye, target, up, fov};
           }),
           py::kw_only(), py::arg("eye") = Vec3{0, 0, 5}, py::arg("target") = Vec3{0, 0, 0},
           py::arg("up") = Vec3{0, 1, 0}, py::arg("fov") = 40.0);

  py::class_<facet::Environment>(m, "Environment", "An equirectangular .exr or .hdr map")
      .def(py::init([](const py::object& file, double intensity, double rotation, const std::string& method,
                       int samples, bool occlusion) {
             const auto ibl = choice<facet::IblMethod>(
                 method, "method",
                 {{"prefiltered", facet::IblMethod::Prefiltered}, {"sampled", facet::IblMethod::Sampled}});
             return facet::Environment{py::module_::import("os").attr("fspath")(file).cast<std::string>(),
                                       intensity,
                                       rotation,
                                       ibl,
                                       samples,
                                       occlusion};
           }),
           py::arg("file"), py::kw_only(), py::arg("intensity") = 1.0, py::arg("rotation") = 0.0,
           py::arg("method") = "prefiltered", py::arg("samples") = 16, py::arg("occlusion") = true);

  py::class_<facet::Scene>(m, "Scene", "A validated scene, built here or loaded with facet.load_scene")
      .def(py::init([](std::vector<facet::Object> objects, std::vector<facet::Material> materials,
                       std::vector<facet::Light> lights, std::optional<facet::Camera> camera,
                       std::optional<facet::Environment> environment, std::pair<int, int> size) {
             return facet::buildScene({camera, std::move(materials), std::move(objects), std::move(lights), environment,
                                       size.first, size.second});
           }),
           py::arg("objects"), py::kw_only(), py::arg("materials") = std::vector<facet::Material>{},
           py::arg("lights") = std::vector<facet::Light>{}, py::arg("camera") = py::none(),
           py::arg("environment") = py::none(), py::arg("size") = std::pair<int, int>{512, 512})
      .def_property_readonly(
          "size",
          [](const facet::Scene& s) {
            return std::pair<int, int>{s.width(), s.height()};
          },
          "The image size (width, height) it renders at")
      .def_property_readonly("object_count", &facet::Scene::objectCount, "How many objects it holds");
  m.def(
      "load_scene", [](const py::object& path) { return sceneOf(path); }, py::arg("path"),
      "A .json scene, an .obj cage or a .gltf/.glb file");

  py::class_<facet::Renderer>(m, "Renderer", "Keeps the GPU device and its compiled kernels between renders")
      .def(py::init<const std::string&>(), py::arg("adapter") = "")
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
          "parity",
          [](facet::Renderer& r, const py::object& scene, std::optional<std::pair<int, int>> size, OptText method) {
            return parityDict(r, scene, settingsOf(size, "gpu", method, std::nullopt, std::nullopt, std::nullopt));
          },
          py::arg("scene"), py::kw_only(), py::arg("size") = py::none(), py::arg("method") = py::none(),
          "As facet.parity, with this renderer's device and kernels");

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
      [](const py::object& scene, std::optional<std::pair<int, int>> size, OptText method, const std::string& adapter) {
        facet::Renderer renderer(adapter);
        return parityDict(renderer, scene, settingsOf(size, "gpu", method, std::nullopt, std::nullopt, std::nullopt));
      },
      py::arg("scene"), py::kw_only(), py::arg("size") = py::none(), py::arg("method") = py::none(),
      py::arg("adapter") = "", "GPU against the CPU reference, AOV by AOV; returns the report as a dict");
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
}

// What the Python module's files share: Vec3 as a tuple, numpy arrays that
// own their values, named choices, and the scene bindings' entry point.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <initializer_list>
#include <stdexcept>
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

namespace facet_python {

using facet::Vec3;
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using OptVec = std::optional<Vec3>;
using OptText = std::optional<std::string>;
using OptReal = std::optional<double>;

// A numpy view of `values`, which moves into a capsule the array owns.
template <class T>
py::array ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), owner);
}

// A scene's values handed out as a tuple, so that an append or an item
// assignment, which could change only a copy, is refused instead of ignored.
template <class T>
py::tuple tupleOf(const std::vector<T>& values) {
  py::tuple out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = py::cast(values[i]);
  return out;
}

// The value `name` names among `options`; anything else is an Error listing them.
template <class T>
T choice(const std::string& name, const char* argument, std::initializer_list<std::pair<const char*, T>> options) {
  std::string list;
  for (const auto& [key, value] : options) {
    if (name == key) return value;
    list += (list.empty() ? "" : ", ") + std::string(key);
  }
  throw facet::Error(facet::ErrorKind::BadInput, std::string(argument) + " '" + name + "': expected one of: " + list);
}

// The name of `chosen` among `options`, the inverse of choice().
template <class T>
const char* choiceName(T chosen, std::initializer_list<std::pair<const char*, T>> options) {
  for (const auto& [key, value] : options)
    if (value == chosen) return key;
  throw std::logic_error("a value without a name among its options");
}

// Directions as an (..., 3) float64 array.
inline Doubles directions(const Doubles& a, const char* name) {
  if (a.ndim() < 1 || a.shape(a.ndim() - 1) != 3)
    throw facet::Error(facet::ErrorKind::BadInput, std::string(name) + ": expected an array of shape (..., 3)");
  return a;
}

inline std::vector<Vec3> vectors(const Doubles& a) {
  std::vector<Vec3> out(std::size_t(a.size() / 3));
  const double* p = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
  return out;
}

// A path (str or os.PathLike) as os.fspath gives it.
inline std::string fspath(const py::object& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

// A Scene, or the scene file at a path (str or os.PathLike).
facet::Scene sceneOf(const py::object& sceneOrPath);

// Material (material_bindings.cpp).
void bindMaterial(py::module_& m);

// Material (through bindMaterial), Cage, Object, Light, Camera, Environment, Scene, SceneObject,
// load_scene and load_cage (scene_bindings.cpp).
void bindScenes(py::module_& m);

// An Image as {aov name: numpy array (height, width[, channels])}, each a view of the render's own plane.
py::dict imageDict(facet::Image&& image);
// Adaptive rounds as `facet render --json`'s `adaptive`.
py::dict adaptiveDict(const facet::SamplingReport& sampling);
// Every public function, method and constructor of `m` wrapped so that a
// call pybind11 cannot match names the unknown keyword as a facet.Error.
void nameUnknownKeywords(py::module_& m, const py::object& error);

// Renderer.preview and Renderer.write_preview.
void bindPreview(py::class_<facet::Renderer>& renderer);

}  // namespace facet_python

// The module's Material: the name and the models' names, then one keyword
// and one property a row of the material parameter table
// (materials/parameter_table.h), so a new row needs no code here.
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "materials/parameter_table.h"
#include "python/bindings.h"

namespace facet_python {
namespace {

using facet::materials::kMaterialParameters;
template <std::size_t I>
using PublicValue = typename std::tuple_element_t<I, std::decay_t<decltype(kMaterialParameters)>>::PublicValue;

// Every keyword's default is its field's empty value: None, or False for a flag.
template <std::size_t... I>
void defineInit(py::class_<facet::Material>& material, std::index_sequence<I...>) {
  material.def(py::init([](const std::string& name, OptText preset, OptText d, OptText g, OptText f,
                           PublicValue<I>... values) {
                 facet::Material m;
                 m.name = name, m.preset = preset, m.distribution = d, m.geometry = g, m.fresnel = f;
                 ((m.*std::get<I>(kMaterialParameters).api = values), ...);
                 return m;
               }),
               py::kw_only(), py::arg("name") = "", py::arg("preset") = py::none(),
               py::arg("distribution") = py::none(), py::arg("geometry") = py::none(),
               py::arg("fresnel") = py::none(), (py::arg(std::get<I>(kMaterialParameters).key) = PublicValue<I>{})...);
}

}  // namespace

void bindMaterial(py::module_& m) {
  py::class_<facet::Material> material(m, "Material", "A material as scene files write it (docs/shading.md)");
  defineInit(material, std::make_index_sequence<facet::materials::kMaterialParameterCount>());
  material.def_readwrite("name", &facet::Material::name)
      .def_readwrite("preset", &facet::Material::preset)
      .def_readwrite("distribution", &facet::Material::distribution)
      .def_readwrite("geometry", &facet::Material::geometry)
      .def_readwrite("fresnel", &facet::Material::fresnel);
  facet::materials::forEachParameter([&](const auto& row) { material.def_readwrite(row.key, row.api); });
}

}  // namespace facet_python

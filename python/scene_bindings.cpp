// The module's scene types: what a scene is made of, loaded scenes that can
// be changed and rendered again, named as the JSON scene format names them
// (docs/scene-format.md).
#include <cstdint>
#include <optional>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include "python/bindings.h"

namespace facet_python {
namespace {

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

constexpr std::initializer_list<std::pair<const char*, facet::LightType>> kLightTypes = {
    {"directional", facet::LightType::Directional},
    {"point", facet::LightType::Point},
    {"spot", facet::LightType::Spot}};
constexpr std::initializer_list<std::pair<const char*, facet::IblMethod>> kIblMethods = {
    {"prefiltered", facet::IblMethod::Prefiltered},
    {"sampled", facet::IblMethod::Sampled},
    {"filtered", facet::IblMethod::Filtered}};

facet::LightType lightType(const std::string& name) { return choice(name, "type", kLightTypes); }
const char* lightTypeName(facet::LightType type) { return choiceName(type, kLightTypes); }
facet::IblMethod iblMethod(const std::string& name) { return choice(name, "method", kIblMethods); }
const char* iblMethodName(facet::IblMethod method) { return choiceName(method, kIblMethods); }

// An object of a Python Scene: changing its material changes that Scene.
struct SceneObject {
  py::object owner;  // the facet.Scene
  int index = 0;
  facet::Scene& scene() const { return owner.cast<facet::Scene&>(); }
};


// Control cages, built from arrays or loaded from .obj files.
void bindCage(py::module_& m) {
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
           py::arg("creases") = std::vector<std::tuple<int, int, double>>{})
      .def_property_readonly(
          "positions",
          [](const facet::Cage& c) {
            std::vector<double> flat;
            for (const Vec3& p : c.positions) flat.insert(flat.end(), {p.x, p.y, p.z});
            py::array array = ownedArray(std::move(flat), {py::ssize_t(c.positions.size()), 3});
            array.attr("setflags")(py::arg("write") = false);  // a copy: writing to it would change nothing
            return array;
          },
          "The control points, a read-only (n, 3) array")
      .def_property_readonly(
          "face_vertex_counts", [](const facet::Cage& c) { return tupleOf(c.faceVertexCounts); },
          "How many vertices each face has")
      .def_property_readonly(
          "face_vertex_indices", [](const facet::Cage& c) { return tupleOf(c.faceVertexIndices); },
          "Each face's vertices in turn, counter-clockwise seen from outside")
      .def_property_readonly(
          "creases",
          [](const facet::Cage& c) {
            std::vector<std::tuple<int, int, double>> out;
            for (const facet::Crease& e : c.creases) out.emplace_back(e.v0, e.v1, e.sharpness);
            return tupleOf(out);
          },
          "(v0, v1, sharpness) of each creased edge; sharpness >= 10 is infinitely sharp");
  m.def(
      "load_cage", [](const py::object& path) { return facet::loadCage(fspath(path)); }, py::arg("path"),
      "An OpenSubdiv-style .obj control cage, read as a scene file's mesh is; a cage with texture coordinates, "
      "corners, holes or subdivision tags is refused (load it with load_scene)");
}

// Lights, cameras and environments are values: their fields are read-only,
// so that changing a copy a scene handed out cannot look like changing the
// scene; replace() makes the changed copy to assign back.
void bindLight(py::module_& m) {
  py::class_<facet::Light>(m, "Light", "A punctual light, with a scene file's lights[] fields; color is c_light")
      .def(py::init([](const std::string& type, Vec3 color, Vec3 position, Vec3 direction, double inner, double outer) {
             return facet::Light{lightType(type), color, position, direction, inner, outer};
           }),
           py::arg("type") = "directional", py::kw_only(), py::arg("color") = Vec3{1, 1, 1},
           py::arg("position") = Vec3{0, 0, 0}, py::arg("direction") = Vec3{0, -1, 0}, py::arg("inner_cone") = 30.0,
           py::arg("outer_cone") = 45.0)
      .def_property_readonly(
          "type", [](const facet::Light& l) { return lightTypeName(l.type); }, "directional, point or spot")
      .def_readonly("color", &facet::Light::color, "c_light")
      .def_readonly("position", &facet::Light::position, "point and spot lights")
      .def_readonly("direction", &facet::Light::direction, "the way the light travels: directional and spot lights")
      .def_readonly("inner_cone", &facet::Light::innerCone, "spot: half-angle in degrees of full light")
      .def_readonly("outer_cone", &facet::Light::outerCone, "spot: half-angle in degrees beyond which none")
      .def(
          "replace",
          [](facet::Light l, OptText type, OptVec color, OptVec position, OptVec direction, OptReal inner,
             OptReal outer) {
            if (type) l.type = lightType(*type);
            l.color = color.value_or(l.color);
            l.position = position.value_or(l.position);
            l.direction = direction.value_or(l.direction);
            l.innerCone = inner.value_or(l.innerCone);
            l.outerCone = outer.value_or(l.outerCone);
            return l;
          },
          py::kw_only(), py::arg("type") = py::none(), py::arg("color") = py::none(), py::arg("position") = py::none(),
          py::arg("direction") = py::none(), py::arg("inner_cone") = py::none(), py::arg("outer_cone") = py::none(),
          "A copy with the fields given changed");
}

void bindCamera(py::module_& m) {
  py::class_<facet::Camera>(m, "Camera", "A pinhole camera, with a scene file's camera fields; fov is vertical")
      .def(py::init([](Vec3 eye, Vec3 target, Vec3 up, double fov) {
             return facet::Camera{eye, target, up, fov};
           }),
           py::kw_only(), py::arg("eye") = Vec3{0, 0, 5}, py::arg("target") = Vec3{0, 0, 0},
           py::arg("up") = Vec3{0, 1, 0}, py::arg("fov") = 40.0)
      .def_readonly("eye", &facet::Camera::eye, "Where the camera is")
      .def_readonly("target", &facet::Camera::target, "What it looks at")
      .def_readonly("up", &facet::Camera::up, "Which way is up in the image")
      .def_readonly("fov", &facet::Camera::fov, "Vertical field of view in degrees, (0, 179]")
      .def(
          "replace",
          [](facet::Camera c, OptVec eye, OptVec target, OptVec up, OptReal fov) {
            return facet::Camera{eye.value_or(c.eye), target.value_or(c.target), up.value_or(c.up),
                                 fov.value_or(c.fov)};
          },
          py::kw_only(), py::arg("eye") = py::none(), py::arg("target") = py::none(), py::arg("up") = py::none(),
          py::arg("fov") = py::none(), "A copy with the fields given changed");
}

void bindEnvironment(py::module_& m) {
  py::class_<facet::Environment>(m, "Environment",
                                 "An equirectangular .exr or .hdr map, with a scene file's environment fields")
      .def(py::init([](const py::object& file, double intensity, double rotation, OptText method,
                       std::optional<int> samples, bool occlusion) {
             return facet::Environment{fspath(file), intensity, rotation,
                                       method ? std::optional(iblMethod(*method)) : std::nullopt, samples, occlusion};
           }),
           py::arg("file"), py::kw_only(), py::arg("intensity") = 1.0, py::arg("rotation") = 0.0,
           py::arg("method") = py::none(), py::arg("samples") = py::none(), py::arg("occlusion") = true)
      .def_readonly("file", &facet::Environment::file,
                    "The map (a loaded scene's may be the default studio map's name, or empty for a uniform colour)")
      .def_readonly("intensity", &facet::Environment::intensity, "What the map is scaled by")
      .def_readonly("rotation", &facet::Environment::rotation, "Degrees about +y")
      .def_property_readonly(
          "method",
          [](const facet::Environment& e) -> OptText {
            return e.method ? OptText(iblMethodName(*e.method)) : std::nullopt;
          },
          "The lighting method: sampled, prefiltered or filtered; None: chosen, sampled where paths run")
      .def_readonly("samples", &facet::Environment::samples,
                    "Sampled, filtered: pairs per camera sample; None: chosen, 16 unless paths run")
      .def_readonly("occlusion", &facet::Environment::occlusion, "sampled, filtered: shadow rays on")
      .def(
          "replace",
          [](facet::Environment e, const py::object& file, OptReal intensity, OptReal rotation, OptText method,
             std::optional<int> samples, std::optional<bool> occlusion) {
            if (!file.is_none()) e.file = fspath(file);
            e.intensity = intensity.value_or(e.intensity);
            e.rotation = rotation.value_or(e.rotation);
            if (method) e.method = iblMethod(*method);
            if (samples) e.samples = samples;
            e.occlusion = occlusion.value_or(e.occlusion);
            return e;
          },
          py::kw_only(), py::arg("file") = py::none(), py::arg("intensity") = py::none(),
          py::arg("rotation") = py::none(), py::arg("method") = py::none(), py::arg("samples") = py::none(),
          py::arg("occlusion") = py::none(), "A copy with the fields given changed");
}

// A Python value as the JSON text --set and scene files take: json.dumps,
// with paths as the strings os.fspath makes of them.
std::string jsonText(const py::object& value) {
  const py::module_ json = py::module_::import("json");
  return json.attr("dumps")(value, py::arg("default") = py::module_::import("os").attr("fspath")).cast<std::string>();
}

void bindTransform(py::module_& m) {
  py::class_<facet::Transform>(m, "Transform",
                               "Where an object stands, as a scene file's objects[].transform: scaled, then rotated "
                               "(degrees about x, then y, then z), then translated")
      .def(py::init([](Vec3 translate, Vec3 rotate, Vec3 scale) {
             return facet::Transform{translate, rotate, scale};
           }),
           py::kw_only(), py::arg("translate") = Vec3{0, 0, 0}, py::arg("rotate") = Vec3{0, 0, 0},
           py::arg("scale") = Vec3{1, 1, 1})
      .def_readonly("translate", &facet::Transform::translate, "The move, last")
      .def_readonly("rotate", &facet::Transform::rotate, "Degrees about x, then y, then z")
      .def_readonly("scale", &facet::Transform::scale, "Per axis, first");
}

// Objects as a Scene is given them, and as it hands them out.
void bindObjects(py::module_& m) {
  bindTransform(m);
  py::class_<facet::Object>(m, "Object", "A cage with the index of its material in the scene's materials")
      .def(py::init([](facet::Cage cage, int material, const std::string& name, bool subdivided,
                       const std::optional<facet::Transform>& transform) {
             return facet::Object{name, std::move(cage), material, subdivided, transform.value_or(facet::Transform{})};
           }),
           py::arg("cage"), py::kw_only(), py::arg("material") = 0, py::arg("name") = "", py::arg("subdivided") = true,
           py::arg("transform") = py::none());

  py::class_<SceneObject>(m, "SceneObject", "One object of a Scene, as scene.objects lists them")
      .def_property_readonly(
          "name", [](const SceneObject& o) { return o.scene().objectName(o.index); }, "Its name")
      .def_property(
          "material", [](const SceneObject& o) { return o.scene().materialName(o.index); },
          [](SceneObject& o, const py::object& material) {
            if (py::isinstance<py::str>(material) || py::hasattr(material, "__fspath__"))
              o.scene().setMaterial(o.index, fspath(material));
            else
              o.scene().setMaterial(o.index, material.cast<facet::Material>());
          },
          "Its material's name; assign a Material, a preset name or a material file (.json) to change it")
      .def_property(
          "transform", [](const SceneObject& o) { return o.scene().transform(o.index); },
          [](SceneObject& o, const facet::Transform& t) { o.scene().setTransform(o.index, t); },
          "The Transform that places its cage, as its scene file's transform; assign one to move it");
}

// The Scene that holds the objects with their materials, camera, environment and lights.
void bindScene(py::module_& m) {
  bindObjects(m);
  py::class_<facet::Scene>(m, "Scene",
                           "A validated scene, built here or loaded with facet.load_scene; its objects' materials, "
                           "camera, environment and lights can be changed, and the next render renders the change")
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
      .def_property_readonly("object_count", &facet::Scene::objectCount, "How many objects it holds")
      .def_property_readonly(
          "objects",
          [](const py::object& self) {
            py::tuple out(self.cast<const facet::Scene&>().objectCount());
            for (int i = 0; i < int(out.size()); ++i) out[std::size_t(i)] = py::cast(SceneObject{self, i});
            return out;
          },
          "Its objects, in order: a tuple, changed through add_object, remove_object and move_object")
      .def_property_readonly(
          "material_names", [](const facet::Scene& s) { return tupleOf(s.materialNames()); },
          "Its materials' names, in the order an Object's material index counts them")
      .def(
          "add_object",
          [](facet::Scene& s, const facet::Object& object, const py::object& material) {
            facet::Scene changed = s;
            const int index = changed.addObject(object);
            if (py::isinstance<py::str>(material) || py::hasattr(material, "__fspath__"))
              changed.setMaterial(index, fspath(material));
            else if (!material.is_none())
              changed.setMaterial(index, material.cast<facet::Material>());
            s = changed;
            return index;
          },
          py::arg("object"), py::kw_only(), py::arg("material") = py::none(),
          "Adds an Object after the others and returns its index; material (a Material, a preset name or a "
          "material file) in place of the object's material index")
      .def("remove_object", &facet::Scene::removeObject, py::arg("index"),
           "Removes an object; the scene keeps at least one")
      .def("move_object", &facet::Scene::moveObject, py::arg("index"), py::arg("to"),
           "Puts an object at index `to`, the others keeping their order")
      .def(
          "set",
          [](facet::Scene& s, const std::string& path, const py::object& value) { s.set(path, jsonText(value)); },
          py::arg("path"), py::arg("value"),
          "What `facet render --set PATH=VALUE` does to a scene file: set(\"materials.gold.roughness\", 0.5); "
          "PATH in render, camera, lights, environment, materials.NAME or objects[N]")
      .def_property("camera", &facet::Scene::camera, &facet::Scene::setCamera, "The camera (assign a Camera)")
      .def_property("environment", &facet::Scene::environment, &facet::Scene::setEnvironment,
                    "The environment, or None (assign an Environment or None)")
      .def_property(
          "lights", [](const facet::Scene& s) { return tupleOf(s.lights()); }, &facet::Scene::setLights,
          "The lights, a tuple (assign a list of Light)")
      .def_property_readonly(
          "warnings", [](const facet::Scene& s) { return tupleOf(s.warnings()); },
          "What the file says that facet renders otherwise, one line each");
  m.def(
      "load_scene",
      [](const py::object& path, const std::string& variant) { return facet::loadScene(fspath(path), variant); },
      py::arg("path"), py::kw_only(), py::arg("variant") = "",
      "A .json scene, an .obj cage or a .gltf/.glb file; variant: a glTF file's material variant by name "
      "(KHR_materials_variants)");
  m.def(
      "load_dict",
      [](const py::dict& scene, const py::object& folder) {
        return facet::sceneFromJson(jsonText(scene), fspath(folder));
      },
      py::arg("scene"), py::kw_only(), py::arg("folder") = ".",
      "A scene file's JSON as a dict (docs/scene-format.md); the files it names are relative to folder");
}

}  // namespace

facet::Scene sceneOf(const py::object& sceneOrPath) {
  if (py::isinstance<facet::Scene>(sceneOrPath)) return sceneOrPath.cast<facet::Scene>();
  return facet::loadScene(fspath(sceneOrPath));
}

void bindScenes(py::module_& m) {
  bindMaterial(m);
  bindCage(m);
  bindLight(m);
  bindCamera(m);
  bindEnvironment(m);
  bindScene(m);
}

}  // namespace facet_python

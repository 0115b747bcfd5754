// Scenes: loaded from a file (.json, .obj cage, .gltf/.glb), given as a
// scene file's JSON, or described in code as plain data, validated into a
// Scene whose objects, materials, camera, environment and lights can then be
// added, removed and changed, each change validated by the scene file's rules.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace facet {
namespace v0 {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// A material as a scene file writes it (docs/shading.md): every field is
// optional; a preset gives the rest. distribution, geometry and fresnel take
// the names `facet brdf --help` lists (ggx, smith-ggx-correlated, schlick, ...).
struct Material {
  std::string name;
  std::optional<std::string> preset;
  std::optional<std::string> distribution;
  std::optional<std::string> geometry;
  std::optional<std::string> fresnel;
  std::optional<double> alpha;      // microfacet alpha
  std::optional<double> roughness;  // perceptual: alpha = roughness^2
  std::optional<Vec3> f0;
  std::optional<Vec3> ior;
  std::optional<Vec3> eta;
  std::optional<Vec3> k;
  std::optional<Vec3> diffuse;
  bool energyCompensation = false;  // multiple-scattering compensation of the specular lobe
  // Transmission (docs/shading.md, "Transmission"); the transparent presets
  // set transmission 1, and 0 makes them opaque.
  std::optional<double> transmission;  // glTF's factor, 0..1
  std::optional<bool> thinWalled;
  std::optional<double> thickness;  // thin-walled: the wall's, for absorption
  std::optional<Vec3> attenuationColor;
  std::optional<double> attenuationDistance;  // > 0; absent: no absorption
  // Anisotropy (docs/shading.md, "Anisotropy"): strength 0..1 stretches the
  // roughness along the tangent, turned by the rotation (radians) about the
  // normal.
  std::optional<double> anisotropy;
  std::optional<double> anisotropyRotation;
  // A clear coat over the rest (docs/shading.md, "Clear coat"): its strength
  // in [0, 1] and perceptual roughness, KHR_materials_clearcoat's factors.
  std::optional<double> clearcoat;
  std::optional<double> clearcoatRoughness;
  // A sheen between the base and any coat (docs/shading.md, "Sheen"): its
  // linear RGB color in [0, 1] and roughness, KHR_materials_sheen's factors.
  std::optional<Vec3> sheenColor;
  std::optional<double> sheenRoughness;
  // A thin film over the base (docs/shading.md, "Iridescence"): its strength
  // in [0, 1], index and thickness in nanometres,
  // KHR_materials_iridescence's factors.
  std::optional<double> iridescence;
  std::optional<double> iridescenceIor;
  std::optional<double> iridescenceThickness;
  // glTF's metallic-roughness parameters, given together in place of
  // diffuse, f0 and a preset: c_diff = base (1 - metallic), F(0) =
  // mix(0.04, base, metallic).
  std::optional<Vec3> baseColor;
  std::optional<double> metallic;
};

// A Catmull-Clark control cage in world space; indices are 0-based and each
// face lists its vertices counter-clockwise seen from outside.
struct Crease {
  int v0 = 0, v1 = 0;
  double sharpness = 0;  // >= 10: infinitely sharp
};
struct Cage {
  std::vector<Vec3> positions;
  std::vector<int> faceVertexCounts;
  std::vector<int> faceVertexIndices;
  std::vector<Crease> creases;
};

// Where an object stands over its cage, as a scene file's
// objects[].transform writes it: scaled, then rotated (degrees about x, then
// y, then z), then translated. The identity leaves the cage where it is.
struct Transform {
  Vec3 translate{0, 0, 0};
  Vec3 rotate{0, 0, 0};  // degrees
  Vec3 scale{1, 1, 1};
};

struct Object {
  std::string name;
  Cage cage;
  // Index into SceneDescription::materials, or a Scene's materialNames()
  // for Scene::addObject.
  int material = 0;
  bool subdivided = true;  // false: the polygons as authored
  Transform transform;
};

enum class LightType { Directional, Point, Spot };
// color is c_light: what a white Lambertian surface facing the light reflects.
struct Light {
  LightType type = LightType::Directional;
  Vec3 color{1, 1, 1};
  Vec3 position{0, 0, 0};
  Vec3 direction{0, -1, 0};  // the way the light travels
  double innerCone = 30;     // degrees
  double outerCone = 45;
};

struct Camera {
  Vec3 eye{0, 0, 5};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov = 40;  // vertical, degrees
};

enum class IblMethod { Sampled, Prefiltered, Filtered };
struct Environment {
  // .exr or .hdr, equirectangular; a loaded scene's may also be the default
  // studio map's name, or empty for a uniform colour.
  std::string file;
  double intensity = 1;
  double rotation = 0;  // degrees about +y
  // None: chosen, prefiltered unless paths run, then sampled with occlusion
  // (docs/rendering.md, "Light transport chosen by the scene").
  std::optional<IblMethod> method;
  // Sampled, filtered: pairs per camera sample. None: chosen, 16 unless
  // facet chooses paths (docs/rendering.md, "Light transport chosen by the scene").
  std::optional<int> samples;
  bool occlusion = true;  // sampled, filtered, with a method given
};

// No camera: framed from the default direction; no lights: the default key
// light; no materials: grey plastic.
struct SceneDescription {
  std::optional<Camera> camera;
  std::vector<Material> materials;
  std::vector<Object> objects;
  std::vector<Light> lights;
  std::optional<Environment> environment;
  int width = 512, height = 512;
};

namespace detail {
struct SceneData;
}

// A validated scene, cheap to copy: copies share its data until one of them
// is changed. A change is validated as the scene file's field of that name
// (camera.fov, lights[0].inner_cone, objects[1].material, ...) and throws
// Error (BadInput) with that field's rule, the scene unchanged; the next
// render renders what it now holds. `object` counts from 0 in file order.
class Scene {
 public:
  // From loadScene or buildScene; throws Error (BadInput) on no data.
  explicit Scene(std::shared_ptr<const detail::SceneData> data);
  const detail::SceneData& data() const { return *data_; }
  int width() const;
  int height() const;
  int objectCount() const;
  // What the file says that facet renders otherwise ("FILE: FIELD: what
  // facet does instead"), as `facet render` prints them.
  std::vector<std::string> warnings() const;

  std::string objectName(int object) const;
  // The material's name: its key in the file's materials, a preset's or
  // material file's name, or empty for one written inline.
  std::string materialName(int object) const;
  // Every material of the scene, named as materialName names them, in the
  // order an Object's `material` counts them.
  std::vector<std::string> materialNames() const;

  // Adds `object` after the others, validated as buildScene validates
  // objects (errors name objects[N], N its index), and returns its index.
  int addObject(const Object& object);
  // Refuses to leave the scene without objects.
  void removeObject(int object);
  // Puts `object` at index `to`, the others keeping their order.
  void moveObject(int object, int to);
  // The transform that places the object's cage: its scene file's
  // objects[].transform or its Object's, the identity where neither gave
  // one; one its file writes as a matrix, which a Transform cannot hold,
  // throws. setTransform replaces it: the cage is placed as the file's
  // transform would place it.
  Transform transform(int object) const;
  void setTransform(int object, const Transform& transform);

  // What `facet render --set PATH=VALUE` does to a scene file
  // (docs/scene-format.md, "The command line: --material and --set"), done
  // to this scene: VALUE is JSON where it parses as JSON (16, true,
  // [0, 1, 2], {"preset": "gold"}), else a string. PATH names a field of
  // render, camera, lights, environment, materials.NAME (a material of the
  // file's materials block, or one set before) or objects[N] (its material,
  // transform, name or subdivision). Files are relative to the scene file's
  // folder, as there; to the working folder for a scene built in code.
  void set(const std::string& path, const std::string& value);
  void setMaterial(int object, const Material& material);
  // A preset name or a material file (.json, relative to the working
  // folder), as a scene file's objects[].material names them.
  void setMaterial(int object, const std::string& reference);

  Camera camera() const;
  void setCamera(const Camera& camera);
  // The file is read again only when it differs from the current one's.
  std::optional<Environment> environment() const;
  void setEnvironment(const std::optional<Environment>& environment);
  std::vector<Light> lights() const;
  void setLights(const std::vector<Light>& lights);

 private:
  std::shared_ptr<const detail::SceneData> data_;
};

// An OpenSubdiv-style .obj control cage, read as a scene file's mesh is.
Cage loadCage(const std::string& path);

// All throw Error (BadInput) naming the file or the field and the rule.
Scene loadScene(const std::string& path);
// A glTF file in its material variant `variant` (KHR_materials_variants,
// docs/gltf.md), as facet render --variant loads it.
Scene loadScene(const std::string& path, const std::string& variant);
Scene buildScene(const SceneDescription& description);
// A scene file's JSON document as text (docs/scene-format.md): the Python
// module's dict form. Its files are relative to `folder`; errors name
// "scene" in place of a file.
Scene sceneFromJson(const std::string& json, const std::string& folder = ".");

}  // namespace v0
#ifndef FACET_IMPLEMENTATION  // inside libfacet, facet:: is also the engine's
using namespace v0;
#endif
}  // namespace facet

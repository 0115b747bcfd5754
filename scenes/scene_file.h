// Scene files in, validated plain data out.
//
//   .json         facet's scene format (docs/scene-format.md)
//   .obj          a bare OpenSubdiv-style control cage, subdivided
//   .gltf / .glb  glTF 2.0: meshes rendered as authored, metallic-roughness
//                 materials, cameras and KHR_lights_punctual lights
//
// A scene without a camera is framed from the default direction; one without
// lights gets the default lighting (addDefaultLighting). Errors throw
// InputError naming the file, the line or field, and the rule.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "scenes/scene.h"

namespace facet::scene {

Scene loadScene(const std::filesystem::path& path);

Scene loadJsonScene(const std::filesystem::path& path);
Scene loadGltfScene(const std::filesystem::path& path);
Scene sceneFromCage(ControlCage cage);

// Subdivision as scene files and the command line spell it, nothing for any
// other name; kSubdivisionNames lists the spellings for error messages.
std::optional<Subdivision> subdivisionNamed(std::string_view name);
inline constexpr const char* kSubdivisionNames = "catmull-clark, none";

// Every object of `scene` takes the subdivision `name` spells, whatever its
// file chose. Any other name throws std::invalid_argument
// "<option> '<name>': expected one of: catmull-clark, none".
void overrideSubdivision(Scene& scene, const std::string& name, const std::string& option);

// The material of objects that name none: grey plastic (diffuse 0.5,
// F(0) = 0.04 Schlick, GGX alpha 0.25, height-correlated Smith).
materials::Material defaultMaterial();

// Looks at the centre of all objects' bounds from direction (1, 0.75, 1.5)
// (right, above, in front), far enough for the bounding sphere to fill 90% of
// the vertical field of view.
Camera frameBounds(const Aabb& bounds, double verticalFovDegrees = 40.0);
// A white directional key light (c_light = 1) from above the camera's left shoulder.
Light defaultKeyLight(const Camera& camera);

// The lighting of a scene that names no lights: its environment alone, the
// light it names (a key light beside it would be light nobody asked for);
// the default studio environment (studio_environment.h) where it has none.
void addDefaultLighting(Scene& scene);

// World-space box of every object's control points (which enclose the limit surface).
Aabb cageBounds(const Scene& scene);

}  // namespace facet::scene

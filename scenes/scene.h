// A scene as plain data: what a scene file says, validated, with every path
// resolved and every cage already in world space. Knows no backend.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenes/control_cage.h"
#include "scenes/environment_map.h"
#include "scenes/subdivision_surface.h"
#include "scenes/texture.h"
#include "materials/material.h"

namespace facet::scene {

// Pinhole camera. Pixel (i, j) is sampled at its centre; row 0 is the top.
struct Camera {
  glm::dvec3 eye{0.0, 0.0, 5.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double verticalFovDegrees = 40.0;
};

// The camera at a frame of an animation (scenes/camera_keys.h).
struct CameraKey {
  int frame = 0;
  Camera camera;
};

enum class LightType { Directional, Point, Spot };

// Punctual lights in the course's convention: `color` is c_light, the
// radiance a white Lambertian surface facing the light reflects, so that
// L_o = π f(l, v) c_light (n·l)+. For point and spot lights c_light is given
// at distance 1 and falls off as 1/d²; a spot light also fades from 1 inside
// `innerConeDegrees` to 0 outside `outerConeDegrees` (half-angles).
struct Light {
  LightType type = LightType::Directional;
  glm::dvec3 color{1.0};
  glm::dvec3 position{0.0};              // point, spot
  glm::dvec3 direction{0.0, -1.0, 0.0};  // the way the light travels: directional, spot
  double innerConeDegrees = 30.0;
  double outerConeDegrees = 45.0;
};

enum class IntersectionMethod { Exact, Tessellated };

// Samples per pixel are a square number n²: the points of a scrambled net (rules/camera/sample_plan.h).
inline bool isSquare(int n) {
  int root = 0;
  while ((root + 1) * (root + 1) <= n) ++root;
  return root * root == n;
}
inline constexpr const char* kSamplesPerPixelRule = "samples per pixel must be a square number (an n x n grid)";

// Adaptive sampling's stopping rules (engine/adaptive_render.h): a tile's
// relative standard error, and the camera samples per pixel at most.
inline constexpr double kDefaultNoiseThreshold = 0.02;
inline constexpr int kDefaultMaxSamplesPerPixel = 256;
inline constexpr const char* kNoiseThresholdRule = "expected a number in (0, 1]";
inline constexpr const char* kMaxSppRule = "expected a whole number of samples in [8, 65536] (two rounds of 4)";
inline bool validNoiseThreshold(double t) { return t > 0.0 && t <= 1.0; }
inline bool validMaxSpp(long long spp) { return spp >= 8 && spp <= 65536; }

// Paths (docs/rendering.md, "Paths"): a continuation that
// misses adds nothing because the vertex it left counted the environment with
// its shadow rays, so paths need them.
inline constexpr int kMaxBounces = 64;
inline constexpr const char* kBouncesNeedOcclusionRule =
    "bounces above 0 need the environment lit with its shadow rays (ibl sampled or filtered, occlusion on): a "
    "continuation that misses adds nothing because the vertex it left counted the environment, shadowed";

// How a render takes its camera samples (docs/rendering.md, "Converged by
// default"): one pass of `samplesPerPixel`; adaptive rounds until every
// tile's noise is below `noiseThreshold` or it has `maxSamplesPerPixel`; or,
// where a scene file, the command line or an API states neither, as facet
// chooses from the scene (scenes/sampling_choice.h).
enum class Sampling { Chosen, OnePass, Adaptive };

struct RenderSettings {
  int width = 512;
  int height = 512;
  int samplesPerPixel = 1;  // a square number: stratified sqrt x sqrt
  Sampling sampling = Sampling::OnePass;  // a scene built in code states one pass
  double noiseThreshold = kDefaultNoiseThreshold;
  int maxSamplesPerPixel = kDefaultMaxSamplesPerPixel;
  int bounces = 0;          // continuations per camera sample's path; 0: direct light only
  // False where a scene file, the command line or an API left the bounces
  // and the lobe limits unsaid: facet chooses them from the scene
  // (scenes/light_transport.h). A scene built in code states them.
  bool bouncesStated = true;
  // Continuations of each lobe kind a path may take besides `bounces`
  // (rules/sampling/path_samples.h); -1: no limit of its own.
  int diffuseBounces = -1;
  int glossyBounces = -1;
  int transmissionBounces = -1;
  IntersectionMethod method = IntersectionMethod::Exact;
  // Screen-space tolerance, in pixels, that chooses refinement and dicing
  // levels (see chooseRefinement).
  double pixelTolerance = 0.5;
  std::optional<int> tessellationRate;  // overrides the choice from pixelTolerance
  // Exact method: the largest distance from the ray at which a root is
  // accepted, as a fraction of the scene's bounding-box diagonal. Unset: 1e-9
  // of each object's diagonal on the CPU. The CPU never goes below 8 double
  // ulps of the geometry's largest coordinate, the GPU below 8 float ulps of
  // its largest coordinate relative to the eye (docs/rendering.md).
  std::optional<double> exactTolerance;
};

// How an environment lights the surface: Sampled, a Monte Carlo estimate by
// multiple importance sampling, shadowed when `occlusion`; Prefiltered, the
// split sum (Karis 2013), unshadowed; Filtered, BRDF samples read from the
// map's mip chain (Krivanek & Colbert 2008), shadowed when `occlusion`
// (docs/rendering.md, "Image-based lighting").
enum class IblMethod { Sampled, Prefiltered, Filtered };

// Radiance arriving from world direction w is intensity x map(R^-1 w), R a
// rotation by `rotationDegrees` about +y. Camera rays that miss see it too.
struct Environment {
  std::shared_ptr<const EnvironmentMap> map;
  double intensity = 1.0;
  double rotationDegrees = 0.0;
  IblMethod method = IblMethod::Prefiltered;
  int samples = 16;  // sampled, filtered: pairs per camera sample
  bool occlusion = true;
  // False where nothing said the method or the occlusion: where paths run,
  // facet samples the environment with its shadow rays
  // (scenes/light_transport.h).
  bool methodStated = true;
  // False where nothing said the samples: where facet chooses paths, it
  // chooses the pairs too (scenes/light_transport.h).
  bool samplesStated = true;
  // Sampled, filtered: which random numbers (rules/environment/sampled_environment.h); renders
  // with different seeds are statistically independent.
  std::uint32_t seed = 0;
};

// Whether any lobe kind has a limit of its own.
inline bool limitsLobes(const RenderSettings& r) {
  return r.diffuseBounces >= 0 || r.glossyBounces >= 0 || r.transmissionBounces >= 0;
}

// Whether the environment's light at a surface is decided by shadow rays.
inline bool castsShadowRays(const Environment& environment) {
  return environment.occlusion && environment.method != IblMethod::Prefiltered;
}

// Whether paths of `bounces` count the environment once (kBouncesNeedOcclusionRule).
inline bool pathsCountEnvironmentOnce(int bounces, const std::optional<Environment>& environment) {
  return bounces == 0 || !environment || castsShadowRays(*environment);
}

// Whether the stated bounces and the stated environment method contradict
// each other (kBouncesNeedOcclusionRule): an unstated method is chosen to
// carry the paths.
inline bool bouncesContradictEnvironment(const RenderSettings& r, const std::optional<Environment>& environment) {
  return environment && environment->methodStated && !pathsCountEnvironmentOnce(r.bounces, environment);
}

// How an object's alpha decides where rays find it (glTF's alphaMode).
enum class AlphaMode { Opaque, Mask, Blend };

struct Object {
  std::string name;
  ControlCage cage;  // world space
  int material = 0;  // index into Scene::materials
  // OBJ cages are subdivided, glTF meshes are rendered as authored, unless
  // the scene or the command line says otherwise.
  Subdivision subdivision = Subdivision::CatmullClark;
  // Catmull-Clark only.
  std::optional<int> isolationLevel;  // overrides the choice from pixelTolerance
  EndCapBasis endCaps = EndCapBasis::Gregory;
  // glTF's doubleSided false: rays pass over the back faces (cullsBackFaces).
  bool oneSided = false;
  // glTF's alphaMode (rules/surface/cutout.h): with Mask, rays pass over the
  // surface where alphaFactor x the alpha of alphaTexture, the material's
  // base colour slot, is below alphaCutoff; with Blend, at random with
  // probability 1 - that alpha.
  AlphaMode alphaMode = AlphaMode::Opaque;
  double alphaCutoff = 0.5;
  double alphaFactor = 1.0;
  materials::TextureSlot alphaTexture;
  // The preview's ground in its paths (rules/shading/shadow_catcher.h):
  // camera rays pass over it; continuation rays see the background it
  // catches shadows on. No scene file sets it.
  bool shadowCatcher = false;
  // The preview's holdout (scenes/ground_plane.h): camera rays that hit it
  // see black and end there, counted as covered; continuation rays see it
  // in its material. No scene file sets it.
  bool holdout = false;
};

// Whether rays pass over part of an object's surface by its alpha.
inline bool hasCutout(const Object& object) { return object.alphaMode != AlphaMode::Opaque; }

// Whether rays pass over an object's back faces (docs/rendering.md,
// "One-sided surfaces"): a one-sided object's, unless its material transmits,
// whose inside a path sees through its back faces.
inline bool cullsBackFaces(const Object& object, const materials::Material& material) {
  return object.oneSided && !materials::isTransmissive(material);
}

struct Scene {
  std::filesystem::path source;
  Camera camera;
  std::vector<CameraKey> cameraKeys;  // by frame; empty: `camera` in every frame
  std::vector<materials::Material> materials;
  std::vector<Texture> textures;  // what materials' texture slots index
  std::vector<Object> objects;
  std::vector<Light> lights;
  std::optional<Environment> environment;
  RenderSettings render;
  // What the file says that facet renders otherwise, one line each ("FILE:
  // FIELD: what facet does instead"); the command line prints them.
  std::vector<std::string> warnings;
};

}  // namespace facet::scene

#include "engine/gpu_backend/frame_params.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "engine/camera/camera.h"
#include "rules/rules.h"
#include "scenes/camera_medium.h"
#include "scenes/input_error.h"

namespace facet::gpu_backend {
namespace {

// The largest coordinate of the scene's geometry relative to the eye, the
// origin of the GPU's coordinates.
double largestEyeRelativeCoordinate(const scene::Scene& scene, const scene::SceneGeometry& geometry) {
  double largest = 0;
  for (int axis = 0; axis < 3; ++axis)
    largest = std::max({largest, std::abs(geometry.bounds.lo[axis] - scene.camera.eye[axis]),
                        std::abs(geometry.bounds.hi[axis] - scene.camera.eye[axis])});
  return largest;
}

// The kernels multiply up to four eye-relative lengths in float (a normal's
// squared length, a cross product of derivatives); within this bound every
// such product, and a light's squared distance, stays finite.
constexpr double kMaxEyeRelativeCoordinate = 1e9;

}  // namespace

double rootTolerance(const scene::Scene& scene, const scene::SceneGeometry& geometry) {
  return std::max(scene.render.exactTolerance.value_or(1e-9) * geometry.bounds.diagonal(),
                  std::ldexp(largestEyeRelativeCoordinate(scene, geometry), -20));
}

void checkFloatRange(const scene::Scene& scene, const scene::SceneGeometry& geometry) {
  const auto refuse = [&](const std::string& what, double reach) {
    std::ostringstream detail;
    detail << what << " reaches " << reach << " from the eye; render it with the CPU reference (--backend cpu)";
    throw scene::InputError(scene.source.string(), 0,
                            "the GPU computes in float relative to the eye: coordinates must lie within +-1e9 of it",
                            detail.str());
  };
  const double reach = largestEyeRelativeCoordinate(scene, geometry);
  if (!(reach <= kMaxEyeRelativeCoordinate)) refuse("the geometry", reach);
  for (const scene::Light& light : scene.lights) {
    if (light.type == scene::LightType::Directional) continue;
    const glm::dvec3 offset = glm::abs(light.position - scene.camera.eye);
    const double lightReach = std::max({offset.x, offset.y, offset.z});
    if (!(lightReach <= kMaxEyeRelativeCoordinate)) refuse("a light", lightReach);
  }
  if (scene.environment) {
    const double radiance = scene.environment->intensity * double(scene.environment->map->largestRadiance());
    if (!(radiance <= double(scene::kMaxEnvironmentRadiance))) {
      std::ostringstream detail;
      detail << "its largest texel times the intensity is " << radiance
             << "; lower --env-intensity, or render it with the CPU reference (--backend cpu)";
      throw scene::InputError(scene.source.string(), 0,
                              "the GPU sums the environment in float: its radiance must be at most 1e30", detail.str());
    }
  }
}

gpu_layout::FrameParams frameParams(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                                    std::uint32_t strata, const GpuScene& packed) {
  const rules::f64::CameraFrame camera = camera::cameraFrame(scene.camera, scene.render.width, scene.render.height);
  gpu_layout::FrameParams f{};
  // Rays start at the eye, the origin of the GPU's coordinates.
  f.forwardX = float(camera.forward.x), f.forwardY = float(camera.forward.y), f.forwardZ = float(camera.forward.z);
  f.rightX = float(camera.right.x), f.rightY = float(camera.right.y), f.rightZ = float(camera.right.z);
  f.upX = float(camera.up.x), f.upY = float(camera.up.y), f.upZ = float(camera.up.z);
  f.tanHalfFovY = float(camera.tanHalfFovY);
  f.aspect = float(camera.aspect);
  f.width = float(scene.render.width);
  f.height = float(scene.render.height);
  f.strata = strata;
  f.raysPerPixel = rules::f64::rays_per_pixel(strata);
  f.objectCount = std::uint32_t(scene.objects.size());
  f.rootNode = packed.rootNode;
  f.cellBlockCount = std::uint32_t(packed.blocks);
  f.gridVertexCount = std::uint32_t(packed.gridVertices);
  f.edgeMidpointCount = std::uint32_t(packed.edgeMidpoints);
  f.patchCount = std::uint32_t(packed.patches.size());
  const double diagonal = geometry.bounds.diagonal(), tolerance = rootTolerance(scene, geometry);
  f.tolerance = float(tolerance);
  f.minimumPiece = float(std::max(4 * tolerance, 1e-6 * diagonal));
  f.shadowOffset = float(rules::f64::shadow_ray_offset(diagonal, tolerance));
  f.diffuseBounces = scene.render.diffuseBounces;
  f.glossyBounces = scene.render.glossyBounces;
  f.transmissionBounces = scene.render.transmissionBounces;
  const glm::dvec3 eyeSigma = scene::cameraMedium(scene, geometry).sigma;
  f.eyeSigmaR = float(eyeSigma.x), f.eyeSigmaG = float(eyeSigma.y), f.eyeSigmaB = float(eyeSigma.z);
  return f;
}

}  // namespace facet::gpu_backend

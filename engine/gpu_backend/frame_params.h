// What the kernels read of a frame (the camera, the sampling, the scene's
// sizes and tolerances), and the float range they need: the GPU computes in
// float relative to the eye, the origin of its coordinates
// (docs/rendering.md, "The GPU path").
#pragma once

#include <cstdint>

#include "engine/gpu_backend/gpu_scene.h"
#include "engine/gpu_backend/raycast_layout.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::gpu_backend {

// The exact method's root tolerance on the GPU: 8 float ulps of the scene
// as seen from the eye where 1e-9 of its diagonal is below float's
// resolution.
double rootTolerance(const scene::Scene& scene, const scene::SceneGeometry& geometry);

// Refuses (scene::InputError) a scene whose geometry or lights lie too far
// from the eye, or whose environment is too bright, for float.
void checkFloatRange(const scene::Scene& scene, const scene::SceneGeometry& geometry);

// The frame's camera, sampling, scene sizes and tolerances; the render sets
// the rest (slots per ray, the shading tables' sizes, the fallback capacity,
// each band's pixels).
gpu_layout::FrameParams frameParams(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                                    std::uint32_t strata, const GpuScene& packed);

}  // namespace facet::gpu_backend

// The scalar CPU reference: one camera ray per pixel sample, OpenSubdiv's own
// evaluation of the limit surface, shading through materials/ in double
// precision, shadow rays to every punctual light. Written to be checked, not
// to be fast; rows are spread over the machine's cores.
//
// Conventions both backends share (docs/rendering.md):
//   - samples: an n x n grid of sub-pixel centres (n² = samplesPerPixel); the
//     AOVs come from the ray through the pixel centre;
//   - surfaces are two-sided: normals are flipped to face the eye;
//   - L_o = Σ π f(l, v) c_light (n·l)+ V(l), V from a shadow ray that leaves
//     the surface 1e-6 × scene diagonal along the geometric normal;
//   - plus the environment's reflected radiance by the scene's IBL method
//     (the random numbers of sample s of pixel p come from
//     sample_uniform(p, s, ...), s = 0 the centre ray, 1 + stratum the
//     others); camera rays that miss see the environment;
//   - ids are global: patchId and faceId count on from the previous objects.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::cpu {

struct ReferenceStatistics {
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  double environmentMilliseconds = 0;  // preparing the environment (sampling tables or prefiltering)
};

// `progress` receives the finished fraction, from any thread, at most once
// per row. With a crop, only its pixels are rendered, into an image of the
// crop's size; each equals the same pixel of the whole render. `threadCount`
// 0 takes every core.
Image renderReference(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                      ReferenceStatistics* statistics = nullptr, const std::function<void(double)>& progress = {},
                      const std::optional<PixelRect>& crop = {}, unsigned threadCount = 0);

// The worker threads a render with `threadCount` runs: itself, or every core for 0.
unsigned resolveThreadCount(unsigned threadCount);

}  // namespace facet::cpu

// The scalar CPU reference: one camera ray per pixel sample, OpenSubdiv's own
// evaluation of the limit surface, shading through materials/ in double
// precision, shadow rays to every punctual light. Written to be checked, not
// to be fast; rows are spread over the machine's cores.
//
// Conventions both backends share (docs/rendering.md):
//   - samples: sample 0 through the pixel centre gives the AOVs; above 1 spp
//     the shaded samples are the n² = samplesPerPixel points of a scrambled
//     net over the pixel (rules/camera/camera_samples.h);
//   - surfaces are two-sided: normals are flipped to face the eye;
//   - L_o = Σ π f(l, v) c_light (n·l)+ V(l), V from a shadow ray that leaves
//     the surface along the geometric normal by shadow_ray_offset
//     (rules/shading/lights.h): 1e-6 × scene diagonal, and clear of the
//     root tolerance;
//   - plus the environment's reflected radiance by the scene's IBL method
//     (sampled and filtered: the pairs of camera sample s of pixel p are
//     points of the scrambled net of (p, s, seed),
//     rules/environment/sampled_environment.h);
//     camera rays that miss see the environment;
//   - ids are global: patchId and faceId count on from the previous objects;
//   - with render.bounces above 0, each camera sample that hits continues as
//     a path (path_tracer.h); at 0 the image is the one without paths, bit
//     for bit.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "engine/cpu/path_tracer.h"
#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::cpu {

struct ReferenceStatistics {
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  double environmentMilliseconds = 0;     // preparing the environment (sampling tables or prefiltering)
  std::vector<BounceRays> raysPerBounce;  // with bounces > 0: bounce 0 (camera rays) to the last
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

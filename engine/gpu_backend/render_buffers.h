// The GPU buffers of a render: the scene's geometry (kept while it does not
// change), what shades it, and one band of pixels' rays and results, with
// the band's read-back into the image. Every array is rebased on the eye
// (gpu_scene.h).
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/gpu_backend/gpu_scene.h"
#include "engine/gpu_backend/shading_records.h"
#include "engine/ibl/compensation_tables.h"
#include "engine/ibl/environment_lighting.h"
#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"
#include "scenes/scene.h"

namespace facet::gpu_backend {

struct GeometryBuffers {
  gpu::Buffer nodes, patches, headers, points, normals, texcoords, objects, gridVertices, edgeMidpoints, cellBounds,
      refitOrder;
  std::uint64_t bytes = 0;
};

struct ShadingBuffers {
  gpu::Buffer materials, lights, environmentTexels, environmentTables, environmentLevels, environmentSampling;
  gpu::Buffer compensationTables;
  gpu::Buffer sheenAlbedoRows;
};

// A scene's textures on the device (texture_data.h), often its largest
// arrays: kept by the renderer while the textures rendered are the same
// (scene::sameTextures), as they are round after round of an adaptive render.
struct TextureBuffers {
  std::vector<scene::Texture> textures;  // what the buffers hold
  gpu::Buffer texels, levels, table;
};

// What one band of pixels needs, reused band after band.
struct BandBuffers {
  gpu::Buffer frame, hits, shadowRays, contributions, aovs, rayRadiance, beauty, counters;
  gpu::Buffer cameraFallbacks, shadowFallbacks;  // exact method: FallbackRecords, fallbackCapacity each
  gpu::Buffer pathStates, pathRays, livePaths;  // paths only: a PathState, a PathRayRecord, a path index per camera ray
  gpu::Buffer aovsHost, beautyHost, countersHost;
  std::uint64_t bytes = 0;
};

// Every array of the packed geometry against the device's limits (texel
// buffer elements, storage binding and buffer sizes), before anything is
// allocated or diced: a gpu::Error names the array, what it needs, the limit
// and what to do. GpuRenderer::render checks right after packing.
void checkGeometryLimits(const GpuScene& packed, const gpu::Limits& limits, const std::string& adapter);

GeometryBuffers uploadGeometry(gpu::Device& d, const GpuScene& packed);

ShadingBuffers uploadShading(gpu::Device& d, const scene::Scene& scene, const ibl::EnvironmentLighting* lighting,
                             const EnvironmentData& environment, const ibl::CompensationTables& compensation,
                             const std::vector<glm::vec4>& compensationTexels, const glm::dvec3& origin);

// Throws gpu::Error, naming the limit, where the texels pass the device's.
TextureBuffers uploadTextures(gpu::Device& d, const std::vector<scene::Texture>& textures);

// FNV-1a over the packed arrays: the diced geometry (and the attributes
// uploaded with it) is reused while the packed scene (rebased, with its
// rates), the method and the tolerance are the same.
std::uint64_t geometryKey(const GpuScene& packed, bool tessellated, float tolerance);

// What each pixel of a band holds: its camera rays (the centre ray and the
// samples), each with its shadow-ray slots, and with paths a path state and a
// continuation ray per camera ray.
struct BandShape {
  std::uint64_t raysPerPixel = 1;
  std::uint32_t slotsPerRay = 0;
  bool paths = false;
};

// The pixels of one band: as many as keep the band's buffers (allocateBands,
// with fallback lists of one record per 16 rays) within `budget` bytes
// together and each of its storage buffers within the device's
// maxStorageBufferBindingSize and maxBufferSize; at least 1, at most
// `pixels`. Throws gpu::Error when one pixel alone overflows a buffer: the
// message names the buffer, its need and the limit, then `advice`.
std::uint64_t bandPixelCount(const BandShape& shape, std::uint64_t pixels, std::uint64_t budget,
                             const gpu::Limits& limits, const std::string& adapter, const std::string& advice);

// The settings that make a pixel's rays and slots, as bandPixelCount's advice:
// the samples per pixel, the environment's samples, the lights.
std::string bandAdvice(const scene::Scene& scene);

// With `paths`, the path states and the continuation rays' list too.
BandBuffers allocateBands(gpu::Device& d, std::uint64_t bandPixels, std::uint64_t bandRays, std::uint32_t slots,
                          std::uint32_t fallbackCapacity, bool paths);

// A band's pixels, the `count` from the window's pixel `first` along its
// rows (compute/raycast/common/band_pixels.glsl), read back into the
// window's image; positions return to world space in double.
void readBand(BandBuffers& band, std::uint64_t first, std::uint64_t count, const glm::dvec3& origin, Image& image);

}  // namespace facet::gpu_backend

#include "engine/gpu_backend/render_buffers.h"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <utility>

#include "engine/gpu_backend/raycast_layout.h"
#include "engine/gpu_backend/texture_data.h"

namespace facet::gpu_backend {
namespace {

using gpu::BufferUsage;
namespace layout = gpu_layout;

// Vulkan has no empty buffers, and a binding holds at least one element (one
// texel): an unused array gets that much.
std::uint64_t bufferBytes(std::uint64_t bytes) { return std::max<std::uint64_t>(16, bytes); }

template <class T>
gpu::Buffer upload(gpu::Device& device, const char* label, const std::vector<T>& data, BufferUsage usage) {
  gpu::Buffer buffer = device.createBuffer(
      {label, bufferBytes(std::max(sizeof(T), data.size() * sizeof(T))), usage | BufferUsage::CopyDst});
  if (!data.empty()) device.queue().writeBuffer(buffer, 0, data.data(), data.size() * sizeof(T));
  return buffer;
}

gpu::Buffer storage(gpu::Device& device, const char* label, std::uint64_t bytes,
                    BufferUsage extra = BufferUsage::None) {
  return device.createBuffer({label, bufferBytes(bytes), BufferUsage::Storage | extra});
}

// Each array a kernel reads through one texel buffer must fit the device's
// limit on its elements; `advice` says how to make it smaller.
void checkTexelBuffers(const gpu::Limits& limits, const std::string& adapter,
                       std::initializer_list<std::pair<const char*, std::uint64_t>> arrays, const char* advice) {
  for (const auto& [name, texels] : arrays) {
    if (texels > limits.maxTexelBufferElements)
      throw gpu::Error(std::string(name) + " need " + std::to_string(texels) + " texels in one texel buffer; " +
                       adapter + " addresses at most " + std::to_string(limits.maxTexelBufferElements) + ": " + advice);
    if (texels * 16 > limits.maxBufferSize)
      throw gpu::Error(std::string(name) + " need " + std::to_string(texels * 16) + " bytes in one buffer; " + adapter +
                       "'s maxBufferSize is " + std::to_string(limits.maxBufferSize) + ": " + advice);
  }
}

// The same for arrays read as storage buffers, bounded by
// maxStorageBufferBindingSize.
void checkStorageBuffers(const gpu::Limits& limits, const std::string& adapter,
                         std::initializer_list<std::pair<const char*, std::uint64_t>> arrays, const char* advice) {
  const std::uint64_t maxBytes = std::min(limits.maxStorageBufferBindingSize, limits.maxBufferSize);
  for (const auto& [name, bytes] : arrays)
    if (bytes > maxBytes)
      throw gpu::Error(std::string(name) + " need " + std::to_string(bytes) + " bytes in one storage buffer; " +
                       adapter + " binds at most " + std::to_string(maxBytes) + ": " + advice);
}

}  // namespace

void checkGeometryLimits(const GpuScene& packed, const gpu::Limits& limits, const std::string& adapter) {
  checkTexelBuffers(limits, adapter,
                    {{"the micro-grid's BVH nodes", packed.nodeCount * layout::FACET_BVH4_TEXELS},
                     {"the micro-grid's grid vertices", packed.gridVertices},
                     {"the micro-grid's edge midpoints", packed.edgeMidpoints},
                     {"the micro-grid's cell bounds", packed.cellBounds}},
                    "lower the dicing rate (--tess-level)");
  const char* fewerPatches =
      "the scene has too many patches for this device: lower the objects' isolation, or render it with the CPU "
      "reference (--backend cpu)";
  checkTexelBuffers(limits, adapter,
                    {{"the patch records", packed.patches.size() * layout::FACET_PATCH_RECORD_TEXELS},
                     {"the patch headers", packed.headers.size()},
                     {"the patch points", packed.points.size()},
                     {"the authored normals", packed.normals.size()},
                     {"the texture coordinates", packed.texcoords.size()}},
                    fewerPatches);
  checkStorageBuffers(limits, adapter,
                      {{"the object ranges", packed.objects.size() * sizeof(layout::ObjectRange)},
                       {"the refit order", packed.refitOrder.size() * sizeof(std::uint32_t)}},
                      fewerPatches);
}

std::uint64_t bandPixelCount(const BandShape& shape, std::uint64_t pixels, std::uint64_t budget,
                             const gpu::Limits& limits, const std::string& adapter, const std::string& advice) {
  const std::uint64_t rays = shape.raysPerPixel, slots = std::max(1u, shape.slotsPerRay);
  const std::uint64_t pathBytes = sizeof(layout::PathState) + sizeof(layout::PathRayRecord);
  // Each storage buffer of allocateBands by what one pixel puts in it.
  struct PerPixel {
    const char* name;
    std::uint64_t bytes;
  };
  const PerPixel buffers[] = {{"shadow rays", rays * slots * sizeof(layout::ShadowRayRecord)},
                              {"light contributions", rays * slots * 16},
                              {"camera hits", rays * sizeof(layout::HitRecord)},
                              {"path states", shape.paths ? rays * sizeof(layout::PathState) : 0},
                              {"continuation rays", shape.paths ? rays * sizeof(layout::PathRayRecord) : 0},
                              {"live paths", shape.paths ? rays * sizeof(std::uint32_t) : 0},
                              {"camera ray radiance", rays * 16},
                              {"AOVs", sizeof(layout::PixelAovs)},
                              {"beauty", 16}};
  const std::uint64_t fallbackBytes = 2 * (rays / 16 + 1) * sizeof(layout::FallbackRecord);
  std::uint64_t pixelBytes = fallbackBytes + (shape.paths ? rays * pathBytes : 0);
  for (const PerPixel& buffer : buffers) pixelBytes += buffer.bytes;
  const std::uint64_t maxBinding = std::min(limits.maxStorageBufferBindingSize, limits.maxBufferSize);
  std::uint64_t band = std::min(pixels, std::max<std::uint64_t>(1, budget / pixelBytes));
  for (const PerPixel& buffer : buffers) {
    if (buffer.bytes == 0) continue;
    if (buffer.bytes > maxBinding)
      throw gpu::Error(std::string("one pixel's ") + buffer.name + " need " + std::to_string(buffer.bytes) +
                       " bytes in one storage buffer (" + std::to_string(rays) + " camera rays, " +
                       std::to_string(slots) + " shadow-ray slots each); " + adapter + " binds at most " +
                       std::to_string(maxBinding) + ": " + advice);
    band = std::min(band, maxBinding / buffer.bytes);
  }
  return band;
}

std::string bandAdvice(const scene::Scene& scene) {
  std::string settings = "samples per pixel (--spp, " + std::to_string(scene.render.samplesPerPixel) + ")";
  if (scene.environment)
    settings += ", the environment's samples (--ibl-samples, " + std::to_string(scene.environment->samples) + ")";
  if (!scene.lights.empty()) settings += ", the lights (" + std::to_string(scene.lights.size()) + ")";
  return "lower the " + settings + ", or render with the CPU reference (--backend cpu)";
}

GeometryBuffers uploadGeometry(gpu::Device& d, const GpuScene& packed) {
  const BufferUsage in = BufferUsage::Storage, texel = BufferUsage::Texel;
  // Written by the dicing kernels, read by the tracing ones.
  const BufferUsage diced = BufferUsage::Texel | BufferUsage::StorageTexel;
  GeometryBuffers b;
  b.nodes = d.createBuffer({"BVH nodes", bufferBytes(packed.nodeCount * layout::FACET_BVH4_TEXELS * sizeof(Texel)),
                            diced | BufferUsage::CopyDst});
  if (!packed.topNodes.empty())
    d.queue().writeBuffer(b.nodes, 0, packed.topNodes.data(), packed.topNodes.size() * sizeof(Texel));
  b.patches = upload(d, "patch records", packed.patches, texel);
  b.headers = upload(d, "patch headers", packed.headers, texel);
  b.points = upload(d, "patch points", packed.points, texel);
  b.normals = upload(d, "authored normals", packed.normals, texel);
  b.texcoords = upload(d, "texture coordinates", packed.texcoords, texel);
  b.objects = upload(d, "object ranges", packed.objects, in);
  b.gridVertices = d.createBuffer({"grid vertices", bufferBytes(packed.gridVertices * 16), diced});
  b.edgeMidpoints = d.createBuffer({"edge midpoints", bufferBytes(packed.edgeMidpoints * 16), diced});
  b.cellBounds = d.createBuffer({"cell bounds", bufferBytes(packed.cellBounds * 16), diced});
  b.refitOrder = upload(d, "refit order", packed.refitOrder, in);
  for (const gpu::Buffer* buffer : {&b.nodes, &b.patches, &b.headers, &b.points, &b.normals, &b.texcoords, &b.objects,
                                    &b.gridVertices, &b.edgeMidpoints, &b.cellBounds})
    b.bytes += buffer->size();
  return b;
}

ShadingBuffers uploadShading(gpu::Device& d, const scene::Scene& scene, const ibl::EnvironmentLighting* lighting,
                             const EnvironmentData& environment, const ibl::CompensationTables& compensation,
                             const std::vector<glm::vec4>& compensationTexels, const glm::dvec3& origin) {
  checkTexelBuffers(
      d.limits(), d.adapterInfo().name,
      {{"the environment map", environment.texels.size()}, {"the environment's tables", environment.tables.size()}},
      "use a smaller map");
  const BufferUsage in = BufferUsage::Storage, texel = BufferUsage::Texel;
  ShadingBuffers b;
  b.materials = upload(d, "materials", materialRecords(scene, lighting, compensation), in);
  b.lights = upload(d, "lights", lightRecords(scene, origin), in);
  b.environmentTexels = upload(d, "environment texels", environment.texels, texel);
  b.environmentTables = upload(d, "environment tables", environment.tables, texel);
  b.environmentLevels = upload(d, "environment levels", environment.levels, texel);
  b.environmentSampling = upload(d, "environment sampling", environment.sampling, texel);
  b.compensationTables = upload(d, "compensation tables", compensationTexels, texel);
  b.sheenAlbedoRows = upload(d, "sheen albedo rows", sheenAlbedoRowTexels(scene), texel);
  return b;
}

TextureBuffers uploadTextures(gpu::Device& d, const std::vector<scene::Texture>& textures) {
  const TextureData data = textureData(textures);
  checkTexelBuffers(d.limits(), d.adapterInfo().name, {{"the textures", data.texels.size()}}, "use smaller textures");
  const BufferUsage texel = BufferUsage::Texel;
  return {textures, upload(d, "texture texels", data.texels, texel), upload(d, "texture levels", data.levels, texel),
          upload(d, "texture table", data.textures, texel)};
}

std::uint64_t geometryKey(const GpuScene& packed, bool tessellated, float tolerance) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  auto add = [&hash](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
  };
  auto addVector = [&add](const auto& v) { add(v.data(), v.size() * sizeof(v[0])); };
  addVector(packed.topNodes);
  addVector(packed.patches);
  addVector(packed.headers);
  addVector(packed.points);
  addVector(packed.normals);
  addVector(packed.texcoords);
  addVector(packed.objects);
  add(&tessellated, sizeof tessellated);
  add(&tolerance, sizeof tolerance);
  return hash;
}

BandBuffers allocateBands(gpu::Device& d, std::uint64_t bandPixels, std::uint64_t bandRays, std::uint32_t slots,
                          std::uint32_t fallbackCapacity, bool paths) {
  BandBuffers b;
  if (paths) {
    b.pathStates = storage(d, "path states", bandRays * sizeof(layout::PathState));
    b.pathRays = storage(d, "continuation rays", bandRays * sizeof(layout::PathRayRecord));
    b.livePaths = storage(d, "live paths", bandRays * sizeof(std::uint32_t));
    b.bytes += b.pathStates.size() + b.pathRays.size() + b.livePaths.size();
  }
  const std::uint64_t fallbackBytes = std::max(1u, fallbackCapacity) * sizeof(layout::FallbackRecord);
  b.cameraFallbacks = storage(d, "camera ray fallbacks", fallbackBytes);
  b.shadowFallbacks = storage(d, "shadow ray fallbacks", fallbackBytes);
  b.frame = d.createBuffer({"frame", sizeof(layout::FrameParams), BufferUsage::Uniform | BufferUsage::CopyDst});
  b.hits = storage(d, "camera hits", bandRays * sizeof(layout::HitRecord));
  // A scene without lights, environment or emission has no slots, but each
  // binding still holds one record: such a ray's slots buffers are unused.
  const std::uint64_t slotRecords = bandRays * std::max(1u, slots);
  b.shadowRays = storage(d, "shadow rays", slotRecords * sizeof(layout::ShadowRayRecord));
  b.contributions = storage(d, "light contributions", slotRecords * 16);
  b.aovs = storage(d, "AOVs", bandPixels * sizeof(layout::PixelAovs), BufferUsage::CopySrc);
  b.rayRadiance = storage(d, "camera ray radiance", bandRays * 16);
  b.beauty = storage(d, "beauty", bandPixels * 16, BufferUsage::CopySrc);
  b.counters = storage(d, "counters", sizeof(layout::RenderCounters),
                       BufferUsage::Indirect | BufferUsage::CopyDst | BufferUsage::CopySrc);
  b.aovsHost = d.createBuffer({"AOVs readback", b.aovs.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  b.beautyHost = d.createBuffer({"beauty readback", b.beauty.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  b.countersHost = d.createBuffer({"counter readback", b.counters.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  for (const gpu::Buffer* buffer : {&b.hits, &b.shadowRays, &b.contributions, &b.aovs, &b.rayRadiance, &b.beauty,
                                    &b.cameraFallbacks, &b.shadowFallbacks})
    b.bytes += buffer->size();
  return b;
}

void readBand(BandBuffers& band, std::uint64_t first, std::uint64_t count, const glm::dvec3& origin, Image& image) {
  const auto pixelAovs = band.aovsHost.mapped<layout::PixelAovs>();
  const auto pixelBeauty = band.beautyHost.mapped<glm::vec4>();
  for (std::uint64_t i = 0; i < count; ++i) {
    const layout::PixelAovs& a = pixelAovs[i];
    const std::size_t p = std::size_t(first + i);
    image.beauty[p] = pixelBeauty[i];
    image.depth[p] = a.depth;
    image.position[p] = a.patchId == layout::FACET_NO_HIT
                            ? glm::vec3(0.0f)
                            : glm::vec3(origin + glm::dvec3(a.positionX, a.positionY, a.positionZ));
    image.geometricNormal[p] = {a.geometricX, a.geometricY, a.geometricZ};
    image.shadingNormal[p] = {a.shadingX, a.shadingY, a.shadingZ};
    image.patchId[p] = a.patchId;
    image.faceId[p] = a.faceId;
    image.uv[p] = {a.u, a.v};
    image.texcoord[p] = {a.texcoordS, a.texcoordT};
  }
}

}  // namespace facet::gpu_backend

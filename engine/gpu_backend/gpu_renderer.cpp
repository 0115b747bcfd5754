#include "engine/gpu_backend/gpu_renderer.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "engine/camera/camera.h"
#include "engine/gpu_backend/gpu_scene.h"
#include "engine/gpu_backend/prefilter_gpu.h"
#include "engine/gpu_backend/raycast_layout.h"
#include "engine/gpu_backend/shading_records.h"
#include "engine/gpu_backend/texture_data.h"
#include "engine/ibl/environment_lighting.h"
#include "facet_raycast_kernels/spirv.h"
#include "materials/material.h"
#include "rules/rules.h"
#include "scenes/input_error.h"

namespace facet::gpu_backend {
namespace {

using gpu::BufferUsage;
namespace layout = gpu_layout;

// Bands of pixels keep one band's buffers within this, so a frame's GPU
// arrays stay near it whatever its size (and each binding far below
// lavapipe's 128 MiB).
constexpr std::uint64_t kBandBytes = std::uint64_t(48) << 20;

// Compute passes in the order they run, each with its own timestamps;
// passes of one name are reported as one stage.
enum Stage {
  kDiceGrid,
  kDiceCells,
  kQuadtrees,
  kRefit,
  kIntersect,
  kCompactCameraFallbacks,
  kCameraFallbacks,
  kResolveCameraFallbacks,
  kSurface,
  kCompactShadowRays,
  kShadow,
  kCompactShadowFallbacks,
  kShadowFallbacks,
  kGather,
  kResolve,
  kStageCount
};
const char* const kStageNames[kStageCount] = {
    "dice grid", "dice cells", "quadtrees", "refit", "intersect", "compact", "fallbacks", "fallbacks", "surface",
    "compact",   "shadow rays", "compact",  "shadow fallbacks", "gather",  "resolve"};

std::pair<std::uint32_t, std::uint32_t> workgroups(std::uint64_t invocations) {
  if (invocations > UINT32_MAX) throw gpu::Error("a pass of more than 2^32 invocations");
  const glm::uvec3 grid = rules::f32::workgroup_grid(std::uint32_t(invocations));
  return {grid.x, grid.y};
}

// Vulkan has no empty buffers, and a binding holds at least one element (one
// texel): an unused array gets that much.
std::uint64_t bufferBytes(std::uint64_t bytes) { return std::max<std::uint64_t>(16, bytes); }

template <class T>
gpu::Buffer upload(gpu::Device& device, const char* label, const std::vector<T>& data, BufferUsage usage) {
  gpu::Buffer buffer =
      device.createBuffer({label, bufferBytes(std::max(sizeof(T), data.size() * sizeof(T))), usage | BufferUsage::CopyDst});
  if (!data.empty()) device.queue().writeBuffer(buffer, 0, data.data(), data.size() * sizeof(T));
  return buffer;
}

gpu::Buffer storage(gpu::Device& device, const char* label, std::uint64_t bytes,
                    BufferUsage extra = BufferUsage::None) {
  return device.createBuffer({label, bufferBytes(bytes), BufferUsage::Storage | extra});
}

// A BRDF model as a specialization constant when every object's material
// uses the same one, else -1 (read per material).
double sharedModel(const scene::Scene& scene, int materials::Material::*model) {
  int shared = -1;
  for (const scene::Object& object : scene.objects) {
    const int id = scene.materials[std::size_t(object.material)].*model;
    if (shared >= 0 && shared != id) return -1;
    shared = id;
  }
  return shared;
}

// The scene's buffers for the GPU, rebased on the eye (gpu_scene.h): the
// geometry, kept while it does not change, and what shades it.
struct GeometryBuffers {
  gpu::Buffer nodes, patches, headers, points, normals, texcoords, objects, gridVertices, edgeMidpoints, cellBounds, refitOrder;
  std::uint64_t bytes = 0;
};

struct ShadingBuffers {
  gpu::Buffer materials, lights, environmentTexels, environmentTables, environmentLevels, environmentSampling;
  gpu::Buffer textureTexels, textureLevels, textureTable, compensationTables;
};

GeometryBuffers uploadGeometry(gpu::Device& d, const GpuScene& packed) {
  const std::uint64_t maxTexels = d.limits().maxTexelBufferElements;
  for (const auto& [name, texels] : {std::pair{"BVH nodes", packed.nodeCount * layout::FACET_BVH4_TEXELS},
                                     std::pair{"grid vertices", packed.gridVertices},
                                     std::pair{"cell bounds", packed.cellBounds}})
    if (texels > maxTexels)
      throw gpu::Error(std::string("the micro-grid's ") + name + " need " + std::to_string(texels) + " texels; " +
                       d.adapterInfo().name + " addresses at most " + std::to_string(maxTexels) +
                       " in one texel buffer: lower the dicing rate (--tess-level)");
  const BufferUsage in = BufferUsage::Storage, texel = BufferUsage::Texel;
  // Written by the dicing kernels, read by the tracing ones.
  const BufferUsage diced = BufferUsage::Texel | BufferUsage::StorageTexel;
  GeometryBuffers b;
  b.nodes = d.createBuffer({"BVH nodes", bufferBytes(packed.nodeCount * layout::FACET_BVH4_TEXELS * sizeof(Texel)),
                            diced | BufferUsage::CopyDst});
  if (!packed.topNodes.empty())
    d.queue().writeBuffer(b.nodes, 0, packed.topNodes.data(), packed.topNodes.size() * sizeof(Texel));
  b.patches = upload(d, "patch records", packed.patches, in);
  b.headers = upload(d, "patch headers", packed.headers, texel);
  b.points = upload(d, "patch points", packed.points, texel);
  b.normals = upload(d, "authored normals", packed.normals, texel);
  b.texcoords = upload(d, "texture coordinates", packed.texcoords, texel);
  b.objects = upload(d, "object ranges", packed.objects, in);
  b.gridVertices = d.createBuffer({"grid vertices", bufferBytes(packed.gridVertices * 16), diced});
  b.edgeMidpoints = d.createBuffer({"edge midpoints", bufferBytes(packed.edgeMidpoints * 16), diced});
  b.cellBounds = d.createBuffer({"cell bounds", bufferBytes(packed.cellBounds * 16), diced});
  b.refitOrder = upload(d, "refit order", packed.refitOrder, in);
  for (const gpu::Buffer* buffer : {&b.nodes, &b.patches, &b.headers, &b.points, &b.normals, &b.texcoords, &b.objects, &b.gridVertices,
                                    &b.edgeMidpoints, &b.cellBounds})
    b.bytes += buffer->size();
  return b;
}

ShadingBuffers uploadShading(gpu::Device& d, const scene::Scene& scene, const ibl::EnvironmentLighting* lighting,
                             const EnvironmentData& environment, const ibl::CompensationTables& compensation,
                             const std::vector<glm::vec4>& compensationTexels, const glm::dvec3& origin) {
  const std::uint64_t maxTexels = d.limits().maxTexelBufferElements;
  const TextureData textures = textureData(scene.textures);
  for (const auto& [name, texels] : {std::pair{"the environment map", environment.texels.size()},
                                     std::pair{"the environment's tables", environment.tables.size()},
                                     std::pair{"the textures", textures.texels.size()}})
    if (texels > maxTexels)
      throw gpu::Error(name + std::string(" needs ") + std::to_string(texels) + " texels in one texel buffer; " +
                       d.adapterInfo().name + " addresses at most " + std::to_string(maxTexels) +
                       ": use a smaller map");
  const BufferUsage in = BufferUsage::Storage, texel = BufferUsage::Texel;
  ShadingBuffers b;
  b.materials = upload(d, "materials", materialRecords(scene, lighting, compensation), in);
  b.lights = upload(d, "lights", lightRecords(scene, origin), in);
  b.environmentTexels = upload(d, "environment texels", environment.texels, texel);
  b.environmentTables = upload(d, "environment tables", environment.tables, texel);
  b.environmentLevels = upload(d, "environment levels", environment.levels, texel);
  b.environmentSampling = upload(d, "environment sampling", environment.sampling, texel);
  b.textureTexels = upload(d, "texture texels", textures.texels, texel);
  b.textureLevels = upload(d, "texture levels", textures.levels, texel);
  b.textureTable = upload(d, "texture table", textures.textures, texel);
  b.compensationTables = upload(d, "compensation tables", compensationTexels, texel);
  return b;
}

// FNV-1a over the packed arrays: the diced geometry (and the attributes
// uploaded with it) is reused while the packed scene (rebased, with its
// rates), the method and the tolerance are the same.
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

// What one band of pixels needs, reused band after band.
struct BandBuffers {
  gpu::Buffer frame, hits, shadowRays, contributions, aovs, rayRadiance, beauty, counters;
  gpu::Buffer cameraFallbacks, shadowFallbacks;  // exact method: FallbackRecords, fallbackCapacity each
  gpu::Buffer aovsHost, beautyHost, countersHost;
  std::uint64_t bytes = 0;
};

BandBuffers allocateBands(gpu::Device& d, std::uint64_t bandPixels, std::uint64_t bandRays, std::uint32_t slots,
                          std::uint32_t fallbackCapacity) {
  BandBuffers b;
  const std::uint64_t fallbackBytes = std::max(1u, fallbackCapacity) * sizeof(layout::FallbackRecord);
  b.cameraFallbacks = storage(d, "camera ray fallbacks", fallbackBytes);
  b.shadowFallbacks = storage(d, "shadow ray fallbacks", fallbackBytes);
  b.frame = d.createBuffer({"frame", sizeof(layout::FrameParams), BufferUsage::Uniform | BufferUsage::CopyDst});
  b.hits = storage(d, "camera hits", bandRays * sizeof(layout::HitRecord));
  b.shadowRays = storage(d, "shadow rays", bandRays * slots * sizeof(layout::ShadowRayRecord));
  b.contributions = storage(d, "light contributions", bandRays * slots * 16);
  b.aovs = storage(d, "AOVs", bandPixels * sizeof(layout::PixelAovs), BufferUsage::CopySrc);
  b.rayRadiance = storage(d, "camera ray radiance", bandRays * 16);
  b.beauty = storage(d, "beauty", bandPixels * 16, BufferUsage::CopySrc);
  b.counters = storage(d, "counters", sizeof(layout::RenderCounters),
                       BufferUsage::Indirect | BufferUsage::CopyDst | BufferUsage::CopySrc);
  b.aovsHost = d.createBuffer({"AOVs readback", b.aovs.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  b.beautyHost = d.createBuffer({"beauty readback", b.beauty.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  b.countersHost =
      d.createBuffer({"counter readback", b.counters.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  for (const gpu::Buffer* buffer : {&b.hits, &b.shadowRays, &b.contributions, &b.aovs, &b.rayRadiance,
                                    &b.beauty, &b.cameraFallbacks, &b.shadowFallbacks})
    b.bytes += buffer->size();
  return b;
}

// Every buffer by its binding number: a number names one buffer in every
// kernel (compute/raycast/common/scene_bindings.glsl, trace_bindings.glsl and the
// kernels' own), so each kernel's bind group follows from its layout.
using BindingTable = std::map<std::uint32_t, const gpu::Buffer*>;

BindingTable bindingTable(const GeometryBuffers& g, const ShadingBuffers& s, const BandBuffers& b) {
  return {{0, &b.frame},
          {1, &g.nodes},
          {2, &g.patches},
          {3, &g.points},
          {4, &g.objects},
          {5, &g.gridVertices},
          {6, &g.edgeMidpoints},
          {7, &g.headers},
          {9, &b.hits},
          {10, &b.counters},
          {11, &s.materials},
          {12, &s.lights},
          {13, &b.aovs},
          {14, &b.shadowRays},
          {15, &b.contributions},
          {16, &g.cellBounds},
          {17, &s.compensationTables},
          {18, &b.beauty},
          {19, &s.environmentTexels},
          {20, &s.environmentLevels},
          {21, &s.environmentSampling},
          {22, &b.rayRadiance},
          {23, &s.environmentTables},
          {24, &b.cameraFallbacks},
          {25, &b.shadowFallbacks},
          {26, &g.refitOrder},
          {27, &g.normals},
          {28, &g.texcoords},
          {29, &s.textureTexels},
          {30, &s.textureLevels},
          {31, &s.textureTable}};
}

gpu::BindGroup bindGroup(gpu::Device& d, const gpu::ComputePipeline& pipeline, const std::string& label,
                         const BindingTable& table) {
  gpu::BindGroupLayout groupLayout = pipeline.getBindGroupLayout(0);
  std::vector<gpu::BindGroupEntry> entries;
  for (const gpu::BindGroupLayoutEntry& entry : groupLayout.entries()) entries.push_back({entry.binding, table.at(entry.binding)});
  return d.createBindGroup({label, &groupLayout, std::move(entries)});
}

layout::FrameParams frameParams(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                                std::uint32_t strata, const GpuScene& packed) {
  const rules::f64::CameraFrame camera = camera::cameraFrame(scene.camera, scene.render.width, scene.render.height);
  layout::FrameParams f{};
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
  return f;
}

// GPU timestamps per compute pass; passes of one name are reported as one
// stage, in the order they first ran.
class StageClock {
 public:
  explicit StageClock(gpu::Device& device) : timestamps_(device.createQuerySet({"stage timestamps", 2 * kStageCount})) {}

  gpu::ComputePassEncoder begin(gpu::CommandEncoder& encoder, Stage stage, const gpu::ComputePipeline& pipeline,
                                const gpu::BindGroup& group) {
    ran_[stage] = true;
    gpu::ComputePassEncoder pass =
        encoder.beginComputePass({kStageNames[stage], {&timestamps_, 2u * stage, 2u * stage + 1}});
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    return pass;
  }

  void dispatch(gpu::CommandEncoder& encoder, Stage stage, const gpu::ComputePipeline& pipeline,
                const gpu::BindGroup& group, std::uint64_t invocations) {
    const auto [x, y] = workgroups(invocations);
    begin(encoder, stage, pipeline, group).dispatchWorkgroups(x, y);
  }

  // After the queue is idle: adds the passes of stages first ... last.
  void read(Stage first, Stage last) {
    for (int s = first; s <= last; ++s) {
      if (!ran_[s]) continue;
      const std::vector<double> ns = timestamps_.readTimestampsNs(2u * std::uint32_t(s), 2);
      nanoseconds_[s] += ns[1] - ns[0];
    }
  }

  void report(std::vector<std::pair<std::string, double>>& stages) const {
    for (int s = 0; s < kStageCount; ++s) {
      if (!ran_[s]) continue;
      auto same = std::find_if(stages.begin(), stages.end(), [&](const auto& st) { return st.first == kStageNames[s]; });
      if (same == stages.end())
        stages.emplace_back(kStageNames[s], nanoseconds_[s] * 1e-6);
      else
        same->second += nanoseconds_[s] * 1e-6;
    }
  }

 private:
  gpu::QuerySet timestamps_;
  double nanoseconds_[kStageCount] = {};
  bool ran_[kStageCount] = {};
};

// The runs of consecutive pixels (indices of the full image, the kernels'
// firstPixel) that cover a window: one run when it spans whole rows, else
// one per row.
struct PixelRun {
  std::uint64_t first, count;
};

std::vector<PixelRun> pixelRuns(const PixelRect& window, int width) {
  const auto index = [&](int x, int y) { return std::uint64_t(y) * std::uint64_t(width) + std::uint64_t(x); };
  if (window.width() == width) return {{index(0, window.y0), window.pixelCount()}};
  std::vector<PixelRun> runs;
  for (int y = window.y0; y < window.y1; ++y) runs.push_back({index(window.x0, y), std::uint64_t(window.width())});
  return runs;
}

// A band's pixels, the `count` from full-image pixel `first`, read back into
// the window's image; positions return to world space in double.
void readBand(BandBuffers& band, std::uint64_t first, std::uint64_t count, int width, const PixelRect& window,
              const glm::dvec3& origin, Image& image) {
  const auto pixelAovs = band.aovsHost.mapped<layout::PixelAovs>();
  const auto pixelBeauty = band.beautyHost.mapped<glm::vec4>();
  for (std::uint64_t i = 0; i < count; ++i) {
    const layout::PixelAovs& a = pixelAovs[i];
    const int x = int((first + i) % std::uint64_t(width)), y = int((first + i) / std::uint64_t(width));
    const std::size_t p = image.index(x - window.x0, y - window.y0);
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

}  // namespace

struct GpuRenderer::DicedGeometry {
  std::uint64_t key = 0;
  GeometryBuffers buffers;
};

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
                              "the GPU sums the environment in float: its radiance must be at most 1e30",
                              detail.str());
    }
  }
}

}  // namespace

double rootTolerance(const scene::Scene& scene, const scene::SceneGeometry& geometry) {
  return std::max(scene.render.exactTolerance.value_or(1e-9) * geometry.bounds.diagonal(),
                  std::ldexp(largestEyeRelativeCoordinate(scene, geometry), -20));
}

PipelineCache::PipelineCache(gpu::Device& device) : device_(device) {
  const std::pair<const char*, std::span<const std::uint32_t>> kernels[] = {
      {"dice_grid", raycast::spirv::dice_grid},
      {"dice_cells", raycast::spirv::dice_cells},
      {"build_quadtrees", raycast::spirv::build_quadtrees},
      {"refit_top_levels", raycast::spirv::refit_top_levels},
      {"intersect", raycast::spirv::intersect},
      {"surface", raycast::spirv::surface},
      {"dispatch_args", raycast::spirv::dispatch_args},
      {"fallback", raycast::spirv::fallback},
      {"fallback_resolve", raycast::spirv::fallback_resolve},
      {"shadow", raycast::spirv::shadow},
      {"gather", raycast::spirv::gather},
      {"resolve", raycast::spirv::resolve}};
  for (const auto& [name, code] : kernels) modules_.emplace(name, device_.createShaderModule({name, code}));
}

gpu::ComputePipeline& PipelineCache::get(const char* kernel, const std::vector<gpu::ConstantEntry>& constants) {
  std::string key = kernel;
  for (const gpu::ConstantEntry& c : constants) key += " " + c.key + "=" + std::to_string(c.value);
  auto found = pipelines_.find(key);
  if (found != pipelines_.end()) return found->second;
  return pipelines_.emplace(key, device_.createComputePipeline({key, nullptr, &modules_.at(kernel), "main", constants}))
      .first->second;
}

GpuRenderer::GpuRenderer(gpu::Device& device) : device_(device), pipelines_(device) {}

namespace {

ibl::EnvironmentLighting prepareEnvironment(gpu::Device& d, const scene::Scene& scene) {
  return ibl::prepareEnvironmentLighting(scene, [&](const scene::EnvironmentMap& map, const ibl::ModelPairs& models) {
    const ibl::PrefilterSettings settings;
    // Keyed by the device too: its limits decide how large a map it prefilters whole.
    return ibl::cachedPrefilter(map, models, settings, "gpu " + d.adapterInfo().name,
                                [&] { return prefilterOnGpu(d, map, models, settings); });
  });
}

// The pipelines of one render, by the scene's specialization constants.
struct Kernels {
  gpu::ComputePipeline *intersect, *surface, *dispatchArgs, *shadow, *gather, *resolve;
  gpu::ComputePipeline *cameraFallbacks = nullptr, *resolveCameraFallbacks = nullptr, *shadowFallbacks = nullptr;
};

double environmentMethod(const scene::Scene& scene) {
  if (!scene.environment) return 0;
  switch (scene.environment->method) {
    case scene::IblMethod::Sampled:
      return 1;
    case scene::IblMethod::Prefiltered:
      return 2;
    case scene::IblMethod::Filtered:
      return 3;
  }
  return 0;
}

Kernels kernels(PipelineCache& pipelines, const scene::Scene& scene, const ibl::EnvironmentLighting* lighting,
                const ibl::CompensationTables& compensation, bool tessellated) {
  const std::vector<gpu::ConstantEntry> method{{"METHOD", tessellated ? 1.0 : 0.0}};
  Kernels k{&pipelines.get("intersect", method),
            &pipelines.get("surface", {{"LIGHT_COUNT", double(scene.lights.size())},
                                       {"ENVIRONMENT", environmentMethod(scene)},
                                       {"OCCLUSION", scene.environment && scene.environment->occlusion ? 1.0 : 0.0},
                                       {"ENVIRONMENT_SAMPLES", lighting && lighting->environmentSamples ? 1.0 : 0.0},
                                       {"D_MODEL", sharedModel(scene, &materials::Material::distribution)},
                                       {"G_MODEL", sharedModel(scene, &materials::Material::geometry)},
                                       {"F_MODEL", sharedModel(scene, &materials::Material::fresnel)},
                                       {"TEXTURES", scene.textures.empty() ? 0.0 : 1.0},
                                       {"EMISSION", double(emissionSlots(scene))},
                                       {"COMPENSATION", compensation.tables.empty() ? 0.0 : 1.0}}),
            &pipelines.get("dispatch_args", {}),
            &pipelines.get("shadow", method),
            &pipelines.get("gather", {}),
            &pipelines.get("resolve", {})};
  if (!tessellated) {
    k.cameraFallbacks = &pipelines.get("fallback", {{"SHADOW", 0}});
    k.resolveCameraFallbacks = &pipelines.get("fallback_resolve", {});
    k.shadowFallbacks = &pipelines.get("fallback", {{"SHADOW", 1}});
  }
  return k;
}

// Stage: dicing, the micro-grid and every patch's quadtree, then the top
// levels refitted to them.
void dice(gpu::Device& d, PipelineCache& pipelines, const GpuScene& packed, bool tessellated,
          const BindingTable& table, StageClock& clock) {
  gpu::CommandEncoder encoder = d.createCommandEncoder({"dice"});
  if (tessellated) {
    gpu::ComputePipeline& diceGrid = pipelines.get("dice_grid", {});
    clock.dispatch(encoder, kDiceGrid, diceGrid, bindGroup(d, diceGrid, "dice grid", table),
                   packed.gridVertices + packed.edgeMidpoints);
  }
  gpu::ComputePipeline& diceCells = pipelines.get("dice_cells", {{"METHOD", tessellated ? 1.0 : 0.0}});
  clock.dispatch(encoder, kDiceCells, diceCells, bindGroup(d, diceCells, "dice cells", table), packed.blocks);
  gpu::ComputePipeline& quadtrees = pipelines.get("build_quadtrees", {});
  clock.dispatch(encoder, kQuadtrees, quadtrees, bindGroup(d, quadtrees, "build quadtrees", table),
                 packed.patches.size());
  gpu::ComputePipeline& refit = pipelines.get("refit_top_levels", {});
  clock.begin(encoder, kRefit, refit, bindGroup(d, refit, "refit top levels", table)).dispatchWorkgroups(1);
  d.queue().submit(encoder.finish());
  d.queue().waitIdle();
  clock.read(kDiceGrid, kRefit);
}

// Stages per band: trace and shade, one command buffer, each list worked
// off by an indirect dispatch sized from its length.
void traceBand(gpu::Device& d, const Kernels& k, const BindingTable& table, BandBuffers& band, std::uint64_t rays,
               std::uint64_t pixels, StageClock& clock) {
  auto group = [&](const gpu::ComputePipeline* p, const char* label) { return bindGroup(d, *p, label, table); };
  auto indirect = [&](Stage stage, const gpu::ComputePipeline* p, const gpu::BindGroup& g, std::size_t arguments,
                      gpu::CommandEncoder& encoder) {
    clock.begin(encoder, stage, *p, g).dispatchWorkgroupsIndirect(band.counters, arguments);
  };
  const gpu::BindGroup dispatchArgs = group(k.dispatchArgs, "dispatch args");
  auto compact = [&](Stage stage, gpu::CommandEncoder& encoder) {
    clock.begin(encoder, stage, *k.dispatchArgs, dispatchArgs).dispatchWorkgroups(1);
  };
  gpu::CommandEncoder encoder = d.createCommandEncoder({"render band"});
  encoder.clearBuffer(band.counters);
  clock.dispatch(encoder, kIntersect, *k.intersect, group(k.intersect, "intersect"), rays);
  if (k.cameraFallbacks) {
    compact(kCompactCameraFallbacks, encoder);
    indirect(kCameraFallbacks, k.cameraFallbacks, group(k.cameraFallbacks, "camera ray fallbacks"),
             offsetof(layout::RenderCounters, cameraFallbackX), encoder);
    indirect(kResolveCameraFallbacks, k.resolveCameraFallbacks, group(k.resolveCameraFallbacks, "resolve fallbacks"),
             offsetof(layout::RenderCounters, cameraFallbackX), encoder);
  }
  clock.dispatch(encoder, kSurface, *k.surface, group(k.surface, "surface"), rays);
  compact(kCompactShadowRays, encoder);
  indirect(kShadow, k.shadow, group(k.shadow, "shadow"), offsetof(layout::RenderCounters, shadowX), encoder);
  if (k.shadowFallbacks) {
    compact(kCompactShadowFallbacks, encoder);
    indirect(kShadowFallbacks, k.shadowFallbacks, group(k.shadowFallbacks, "shadow ray fallbacks"),
             offsetof(layout::RenderCounters, shadowFallbackX), encoder);
  }
  clock.dispatch(encoder, kGather, *k.gather, group(k.gather, "gather"), rays);
  clock.dispatch(encoder, kResolve, *k.resolve, group(k.resolve, "resolve"), pixels);
  encoder.copyBufferToBuffer(band.aovs, 0, band.aovsHost, 0, pixels * sizeof(layout::PixelAovs));
  encoder.copyBufferToBuffer(band.beauty, 0, band.beautyHost, 0, pixels * 16);
  encoder.copyBufferToBuffer(band.counters, 0, band.countersHost, 0, band.counters.size());
  d.queue().submit(encoder.finish());
  d.queue().waitIdle();
  clock.read(kIntersect, kResolve);
}

}  // namespace

GpuRenderResult GpuRenderer::render(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                                    const std::function<void(double)>& progress, const std::optional<PixelRect>& crop) {
  const std::uint32_t strata = rules::f64::sample_strata(std::uint32_t(scene.render.samplesPerPixel));
  const bool tessellated = scene.render.method == scene::IntersectionMethod::Tessellated;
  checkFloatRange(scene, geometry);
  const glm::dvec3 origin = scene.camera.eye;
  gpu::Device& d = device_;
  GpuRenderResult result;
  auto wallClock = [](std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };

  // Stage: the environment's tables or prefiltered maps (wall clock).
  auto start = std::chrono::steady_clock::now();
  std::optional<ibl::EnvironmentLighting> lighting;
  if (scene.environment) {
    lighting = prepareEnvironment(d, scene);
    result.stageMilliseconds.emplace_back("environment", wallClock(start));
  }

  // Stage: the BVH's top levels and the patches, packed and uploaded unless
  // the last render diced the same geometry (wall clock).
  start = std::chrono::steady_clock::now();
  const GpuScene packed = packScene(scene, geometry, origin, rootTolerance(scene, geometry), tessellated);
  layout::FrameParams frame = frameParams(scene, geometry, strata, packed);
  frame.slotsPerRay = std::uint32_t(scene.lights.size()) + environmentSlots(lighting ? &*lighting : nullptr) +
                      emissionSlots(scene);
  const EnvironmentData environment = lighting ? environmentData(*lighting, frame) : EnvironmentData{};
  const ibl::CompensationTables compensation = ibl::compensationTables(scene);
  const std::vector<glm::vec4> compensationTexelData = compensationTexels(compensation, frame);
  const std::uint64_t key = geometryKey(packed, tessellated, frame.tolerance);
  const bool reused = diced_ && diced_->key == key;
  if (!reused) diced_ = std::make_shared<DicedGeometry>(DicedGeometry{key, uploadGeometry(d, packed)});
  const GeometryBuffers& geometryBuffers = diced_->buffers;
  const ShadingBuffers shadingBuffers = uploadShading(d, scene, lighting ? &*lighting : nullptr, environment,
                                                      compensation, compensationTexelData, origin);
  result.stageMilliseconds.emplace_back("top levels", wallClock(start));

  const int width = scene.render.width;
  const PixelRect window = crop.value_or(PixelRect::whole(width, scene.render.height));
  const std::uint64_t pixels = window.pixelCount();
  const std::uint64_t slotBytes = sizeof(layout::ShadowRayRecord) + 16;
  const std::uint64_t rayBytes = sizeof(layout::HitRecord) + 16 + frame.slotsPerRay * slotBytes;
  const std::uint64_t pixelBytes = frame.raysPerPixel * rayBytes + sizeof(layout::PixelAovs) + 16;
  const std::uint64_t bandPixels = std::min<std::uint64_t>(pixels, std::max<std::uint64_t>(1, kBandBytes / pixelBytes));
  // Fallbacks are rare (cells Newton leaves undecided); a band whose lists
  // overflow is rendered again with room for all.
  frame.fallbackCapacity = tessellated ? 0 : std::uint32_t(bandPixels * frame.raysPerPixel / 16 + 1024);
  BandBuffers band =
      allocateBands(d, bandPixels, bandPixels * frame.raysPerPixel, frame.slotsPerRay, frame.fallbackCapacity);
  BindingTable table = bindingTable(geometryBuffers, shadingBuffers, band);
  result.cells = packed.cells;

  StageClock clock(d);
  d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
  if (!reused) dice(d, pipelines_, packed, tessellated, table, clock);

  const Kernels k = kernels(pipelines_, scene, lighting ? &*lighting : nullptr, compensation, tessellated);
  result.image = Image(window.width(), window.height());
  std::uint64_t finished = 0;
  for (const PixelRun& run : pixelRuns(window, width)) {
    for (std::uint64_t first = run.first, end = run.first + run.count; first < end;) {
      const std::uint64_t count = std::min(bandPixels, end - first);
      frame.firstPixel = std::uint32_t(first);
      frame.pixelCount = std::uint32_t(count);
      d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
      traceBand(d, k, table, band, count * frame.raysPerPixel, count, clock);
      const layout::RenderCounters counters = band.countersHost.mapped<layout::RenderCounters>()[0];
      const std::uint32_t needed = std::max(counters.cameraFallbacks, counters.shadowFallbacks);
      if (needed > frame.fallbackCapacity) {
        frame.fallbackCapacity = needed;
        band = allocateBands(d, bandPixels, bandPixels * frame.raysPerPixel, frame.slotsPerRay, needed);
        table = bindingTable(geometryBuffers, shadingBuffers, band);
        continue;
      }
      readBand(band, first, count, width, window, origin, result.image);
      result.primaryRays += count * frame.raysPerPixel;
      result.shadowRays += counters.shadowRays;
      result.newtonFallbacks += counters.cameraFallbacks + counters.shadowFallbacks;
      first += count;
      finished += count;
      if (progress) progress(double(finished) / double(pixels));
    }
  }
  result.gpuBytes = geometryBuffers.bytes + band.bytes;
  clock.report(result.stageMilliseconds);
  return result;
}

}  // namespace facet::gpu_backend

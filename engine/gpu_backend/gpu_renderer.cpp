#include "engine/gpu_backend/gpu_renderer.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "engine/camera.hpp"
#include "engine/gpu_backend/prefilter_gpu.h"
#include "engine/gpu_backend/raycast_layout.hpp"
#include "engine/ibl/environment_lighting.h"
#include "facet_raycast_kernels/spirv.h"
#include "materials/material.hpp"

namespace facet::gpu_backend {
namespace {

using gpu::BufferUsage;
namespace layout = gpu_layout;

constexpr std::uint32_t kWorkgroupSize = 64;
constexpr std::uint32_t kMaxWorkgroupsPerDimension = 65535;
constexpr int kBvhStackDepth = 32;  // BVH_STACK in compute/raycast/trace.glsl: depth + 1 entries
// A root is accepted up to `tolerance` off the ray, so its t may be off by
// tolerance / sin(angle): shadow rays start well clear of that.
constexpr double kShadowOffsetInTolerances = 32;
// Bands of pixels keep each ray buffer within this (lavapipe binds at most 128 MiB).
constexpr std::uint64_t kMaxRayBufferBytes = std::uint64_t(64) << 20;

enum Stage { kDice, kRaygen, kIntersect, kSurface, kShadow, kGather, kResolve, kStageCount };
const char* const kStageNames[kStageCount] = {"dice",        "raygen", "intersect", "surface",
                                              "shadow rays", "gather", "resolve"};

// A 2D grid of 64-wide workgroups covering `invocations` (kernels index with
// invocation_index()).
std::pair<std::uint32_t, std::uint32_t> workgroups(std::uint64_t invocations) {
  const std::uint64_t groups = std::max<std::uint64_t>(1, (invocations + kWorkgroupSize - 1) / kWorkgroupSize);
  const std::uint64_t x = std::min<std::uint64_t>(groups, kMaxWorkgroupsPerDimension);
  return {std::uint32_t(x), std::uint32_t((groups + x - 1) / x)};
}

template <class T>
gpu::Buffer upload(gpu::Device& device, const char* label, const std::vector<T>& data, BufferUsage usage) {
  // Vulkan has no empty buffers, and a binding holds at least one element:
  // an unused array gets one element's worth.
  const std::uint64_t bytes = std::max<std::uint64_t>({16, sizeof(T), data.size() * sizeof(T)});
  gpu::Buffer buffer = device.createBuffer({label, bytes, usage | BufferUsage::CopyDst});
  if (!data.empty()) device.queue().writeBuffer(buffer, 0, data.data(), data.size() * sizeof(T));
  return buffer;
}

gpu::Buffer storage(gpu::Device& device, const char* label, std::uint64_t bytes,
                    BufferUsage extra = BufferUsage::None) {
  return device.createBuffer({label, std::max<std::uint64_t>(16, bytes), BufferUsage::Storage | extra});
}

// The scene arrays the kernels read, every object's concatenated.
struct SceneArrays {
  std::vector<layout::PatchBvhNode> nodes;
  std::vector<layout::PatchRecord> patches;
  std::vector<layout::PatchPoint> points;
  std::vector<layout::ObjectRange> objects;
  std::uint64_t gridVertices = 0, edgeMidpoints = 0, rows = 0;
};

SceneArrays sceneArrays(const scene::Scene& scene, const scene::SceneGeometry& geometry) {
  SceneArrays arrays;
  std::uint32_t patchIds = 0, faceIds = 0;
  for (std::size_t i = 0; i < geometry.objects.size(); ++i) {
    const scene::ObjectGeometry& object = geometry.objects[i];
    const scene::PatchBvh& bvh = object.bvh;
    if (bvh.statistics().maxDepth >= kBvhStackDepth)
      throw gpu::Error("object '" + scene.objects[i].name + "': BVH depth " +
                       std::to_string(bvh.statistics().maxDepth) + " exceeds the GPU traversal stack of " +
                       std::to_string(kBvhStackDepth));
    const std::uint32_t rate = std::uint32_t(std::max(1, object.refinement.tessellationRate));
    const std::uint64_t patchCount = bvh.gpuPatches().size();
    layout::ObjectRange range{};
    range.firstNode = std::uint32_t(arrays.nodes.size());
    range.firstPatch = std::uint32_t(arrays.patches.size());
    range.firstPoint = std::uint32_t(arrays.points.size());
    range.patchIdOffset = patchIds;
    range.faceIdOffset = faceIds;
    range.material = std::uint32_t(scene.objects[i].material);
    range.rate = rate;
    range.firstGridVertex = std::uint32_t(arrays.gridVertices);
    range.firstEdgeMidpoint = std::uint32_t(arrays.edgeMidpoints);
    range.firstRow = std::uint32_t(arrays.rows);
    arrays.objects.push_back(range);
    arrays.nodes.insert(arrays.nodes.end(), bvh.gpuNodes().begin(), bvh.gpuNodes().end());
    arrays.patches.insert(arrays.patches.end(), bvh.gpuPatches().begin(), bvh.gpuPatches().end());
    arrays.points.insert(arrays.points.end(), bvh.gpuPoints().begin(), bvh.gpuPoints().end());
    arrays.gridVertices += patchCount * (rate + 1) * (rate + 1);
    arrays.edgeMidpoints += patchCount * 4 * rate;
    arrays.rows += patchCount * rate;
    patchIds += std::uint32_t(object.surface.patchCount());
    faceIds += std::uint32_t(scene.objects[i].cage.faceCount());
  }
  return arrays;
}

std::vector<layout::MaterialRecord> materialRecords(const scene::Scene& scene,
                                                    const ibl::EnvironmentLighting* environment) {
  std::vector<layout::MaterialRecord> records;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const materials::f32::BrdfParams p = materials::toParams32(scene.materials[i]);
    const bool prefiltered = environment && !environment->dfgTable.empty();
    records.push_back({p.d_model, p.g_model, p.f_model, p.alpha, p.f0.x, p.f0.y, p.f0.z, p.eta.x, p.eta.y, p.eta.z,
                       p.k.x, p.k.y, p.k.z, p.diffuse.x, p.diffuse.y, p.diffuse.z,
                       prefiltered ? std::uint32_t(environment->dfgTable[i]) : 0u});
  }
  return records;
}

// Everything the environment's kernels read (compute/raycast/environment.glsl),
// with its offsets and sizes set in `frame`: the map's texels, and in one
// float array what is derived from it.
struct EnvironmentData {
  std::vector<float> tables;
  std::vector<std::uint32_t> alias;  // sampled: the alias table's other texel
  std::vector<layout::EnvironmentLevel> levels;
};

EnvironmentData environmentData(const ibl::EnvironmentLighting& lighting, layout::FrameParams& frame) {
  const scene::Environment& environment = *lighting.environment;
  const scene::EnvironmentMap& map = *environment.map;
  EnvironmentData data;
  std::vector<float>& t = data.tables;
  auto offset = [&] { return std::uint32_t(t.size()); };
  auto append = [&](const auto& values) { t.insert(t.end(), values.begin(), values.end()); };
  frame.environmentIntensity = float(environment.intensity);
  frame.environmentCosRotation = float(lighting.cosRotation);
  frame.environmentSinRotation = float(lighting.sinRotation);
  frame.environmentSamples = std::uint32_t(environment.samples);
  frame.environmentSeed = environment.seed;
  frame.environmentWidth = std::uint32_t(map.width);
  frame.environmentHeight = std::uint32_t(map.height);
  if (environment.method == scene::IblMethod::Sampled) {
    const ibl::EnvironmentDistribution& d = lighting.distribution;
    frame.keepOffset = offset();
    append(d.keep);
    frame.texelPdfOffset = offset();
    append(d.texelPdf);
    data.alias = d.alias;
    return data;
  }
  const ibl::PrefilteredEnvironment& p = lighting.prefiltered;
  data.levels.push_back({0, std::uint32_t(map.width), std::uint32_t(map.height)});  // read from the texels
  for (std::size_t i = 1; i < p.levels.size(); ++i) {
    const ibl::RadianceLevel& level = p.levels[i];
    data.levels.push_back({offset(), std::uint32_t(level.width), std::uint32_t(level.height)});
    append(level.rgb);
  }
  frame.levelCount = std::uint32_t(p.levels.size());
  frame.shOffset = offset();
  for (const glm::dvec3& c : p.irradianceSh) t.insert(t.end(), {float(c.r), float(c.g), float(c.b)});
  frame.dfgOffset = offset();
  frame.dfgSize = p.dfg.empty() ? 0 : std::uint32_t(p.dfg.front().size);
  for (const ibl::DfgTable& table : p.dfg) append(table.scaleBias);
  return data;
}

// Slots per camera ray after the lights': none without an environment; one
// for what it adds without shadow rays; two per pair when they are traced.
std::uint32_t environmentSlots(const scene::Scene& scene) {
  if (!scene.environment) return 0;
  const scene::Environment& e = *scene.environment;
  return e.method == scene::IblMethod::Sampled && e.occlusion ? 2 * std::uint32_t(e.samples) : 1;
}

std::vector<layout::LightRecord> lightRecords(const scene::Scene& scene) {
  std::vector<layout::LightRecord> records;
  for (const scene::Light& light : scene.lights) {
    layout::LightRecord r{};
    r.type = light.type == scene::LightType::Directional ? layout::FACET_LIGHT_DIRECTIONAL
             : light.type == scene::LightType::Point     ? layout::FACET_LIGHT_POINT
                                                         : layout::FACET_LIGHT_SPOT;
    r.colorR = float(light.color.r), r.colorG = float(light.color.g), r.colorB = float(light.color.b);
    r.positionX = float(light.position.x), r.positionY = float(light.position.y), r.positionZ = float(light.position.z);
    r.directionX = float(light.direction.x), r.directionY = float(light.direction.y),
    r.directionZ = float(light.direction.z);
    r.cosOuter = float(std::cos(glm::radians(light.outerConeDegrees)));
    r.cosInner = float(std::cos(glm::radians(light.innerConeDegrees)));
    records.push_back(r);
  }
  return records;
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

layout::FrameParams frameParams(const scene::Scene& scene, const scene::SceneGeometry& geometry, int strata) {
  const camera::CameraFrame camera = camera::cameraFrame(scene.camera, scene.render.width, scene.render.height);
  layout::FrameParams f{};
  f.eyeX = float(camera.eye.x), f.eyeY = float(camera.eye.y), f.eyeZ = float(camera.eye.z);
  f.forwardX = float(camera.forward.x), f.forwardY = float(camera.forward.y), f.forwardZ = float(camera.forward.z);
  f.rightX = float(camera.right.x), f.rightY = float(camera.right.y), f.rightZ = float(camera.right.z);
  f.upX = float(camera.up.x), f.upY = float(camera.up.y), f.upZ = float(camera.up.z);
  f.tanHalfFovY = float(camera.tanHalfFovY);
  f.aspect = float(camera.aspect);
  f.width = float(scene.render.width);
  f.height = float(scene.render.height);
  f.strata = std::uint32_t(strata);
  f.raysPerPixel = strata == 1 ? 1u : std::uint32_t(strata * strata + 1);
  f.objectCount = std::uint32_t(scene.objects.size());
  const double diagonal = geometry.bounds.diagonal();
  double largestCoordinate = 0;
  for (int axis = 0; axis < 3; ++axis)
    largestCoordinate = std::max({largestCoordinate, std::abs(geometry.bounds.lo[axis]),
                                  std::abs(geometry.bounds.hi[axis]), std::abs(scene.camera.eye[axis])});
  const double tolerance =
      std::max(scene.render.exactTolerance.value_or(1e-9) * diagonal, std::ldexp(largestCoordinate, -20));
  f.tolerance = float(tolerance);
  f.minimumPiece = float(std::max(4 * tolerance, 1e-6 * diagonal));
  f.shadowOffset = float(std::max(1e-6 * diagonal, kShadowOffsetInTolerances * tolerance));
  return f;
}

}  // namespace

GpuRenderer::GpuRenderer(gpu::Device& device) : device_(device) {
  const std::pair<const char*, std::span<const std::uint32_t>> kernels[] = {
      {"dice", raycast::spirv::dice},           {"raygen", raycast::spirv::raygen},
      {"intersect", raycast::spirv::intersect}, {"surface", raycast::spirv::surface},
      {"gather", raycast::spirv::gather},       {"resolve", raycast::spirv::resolve}};
  for (const auto& [name, code] : kernels) modules_.emplace(name, device_.createShaderModule({name, code}));
}

gpu::ComputePipeline& GpuRenderer::pipeline(const char* kernel, const std::vector<gpu::ConstantEntry>& constants) {
  std::string key = kernel;
  for (const gpu::ConstantEntry& c : constants) key += " " + c.key + "=" + std::to_string(c.value);
  auto found = pipelines_.find(key);
  if (found != pipelines_.end()) return found->second;
  return pipelines_.emplace(key, device_.createComputePipeline({key, nullptr, &modules_.at(kernel), "main", constants}))
      .first->second;
}

GpuRenderResult GpuRenderer::render(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                                    const std::function<void(double)>& progress) {
  const int width = scene.render.width, height = scene.render.height;
  const int strata = int(std::lround(std::sqrt(scene.render.samplesPerPixel)));
  const bool tessellated = scene.render.method == scene::IntersectionMethod::Tessellated;
  const double method = tessellated ? 1 : 0;
  const std::uint32_t lightCount = std::uint32_t(scene.lights.size());
  gpu::Device& d = device_;

  GpuRenderResult result;
  const auto environmentStart = std::chrono::steady_clock::now();
  std::optional<ibl::EnvironmentLighting> lighting;
  if (scene.environment)
    lighting =
        ibl::prepareEnvironmentLighting(scene, [&](const scene::EnvironmentMap& map, const ibl::ModelPairs& models) {
          const ibl::PrefilterSettings settings;
          // Keyed by the device too: its limits decide how large a map it prefilters whole.
          return ibl::cachedPrefilter(map, models, settings, "gpu " + d.adapterInfo().name,
                                      [&] { return prefilterOnGpu(d, map, models, settings); });
        });

  const SceneArrays arrays = sceneArrays(scene, geometry);
  layout::FrameParams frame = frameParams(scene, geometry, strata);
  frame.slotsPerRay = lightCount + environmentSlots(scene);
  const EnvironmentData environment = lighting ? environmentData(*lighting, frame) : EnvironmentData{};
  if (lighting)
    result.stageMilliseconds.emplace_back(
        "environment",
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - environmentStart).count());
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  const std::uint64_t bandPixels = std::min<std::uint64_t>(
      pixels, std::max<std::uint64_t>(1, kMaxRayBufferBytes / (sizeof(layout::RayRecord) * frame.raysPerPixel *
                                                               std::max(1u, frame.slotsPerRay))));
  const std::uint64_t bandRays = bandPixels * frame.raysPerPixel;

  const BufferUsage in = BufferUsage::Storage;
  gpu::Buffer nodes = upload(d, "BVH nodes", arrays.nodes, in);
  gpu::Buffer patches = upload(d, "patch records", arrays.patches, in);
  gpu::Buffer points = upload(d, "patch points", arrays.points, in);
  gpu::Buffer objects = upload(d, "object ranges", arrays.objects, in);
  gpu::Buffer materialBuffer = upload(d, "materials", materialRecords(scene, lighting ? &*lighting : nullptr), in);
  const std::vector<float> noTexels;
  const std::vector<float>& texels = lighting ? scene.environment->map->rgb : noTexels;
  for (const auto& [name, bytes] : {std::pair{"the environment map's texels", texels.size() * sizeof(float)},
                                    std::pair{"the environment's tables", environment.tables.size() * sizeof(float)}})
    if (bytes > d.limits().maxStorageBufferBindingSize)
      throw gpu::Error(name + std::string(" need ") + std::to_string(bytes >> 20) + " MiB in one binding; " +
                       d.adapterInfo().name + " binds at most " +
                       std::to_string(d.limits().maxStorageBufferBindingSize >> 20) +
                       " MiB: use a smaller map (4096 x 2048 fits lavapipe)");
  gpu::Buffer texelBuffer = upload(d, "environment texels", texels, in);
  gpu::Buffer tableBuffer = upload(d, "environment tables", environment.tables, in);
  gpu::Buffer levelBuffer = upload(d, "environment levels", environment.levels, in);
  gpu::Buffer aliasBuffer = upload(d, "environment aliases", environment.alias, in);
  gpu::Buffer lightBuffer = upload(d, "lights", lightRecords(scene), in);
  const std::uint64_t tessellationScale = tessellated ? 1 : 0;
  gpu::Buffer gridVertices = storage(d, "grid vertices", tessellationScale * arrays.gridVertices * 12);
  gpu::Buffer edgeMidpoints = storage(d, "edge midpoints", tessellationScale * arrays.edgeMidpoints * 12);
  gpu::Buffer rowBounds = storage(d, "row bounds", tessellationScale * arrays.rows * 24);
  gpu::Buffer frameBuffer = d.createBuffer({"frame", sizeof(frame), BufferUsage::Uniform | BufferUsage::CopyDst});
  gpu::Buffer primaryCount = d.createBuffer({"camera ray batch", 16, BufferUsage::Uniform | BufferUsage::CopyDst});
  gpu::Buffer shadowCount = d.createBuffer({"shadow ray batch", 16, BufferUsage::Uniform | BufferUsage::CopyDst});
  gpu::Buffer rays = storage(d, "camera rays", bandRays * sizeof(layout::RayRecord));
  gpu::Buffer hits = storage(d, "camera hits", bandRays * sizeof(layout::HitRecord));
  gpu::Buffer shadowRays = storage(d, "shadow rays", bandRays * frame.slotsPerRay * sizeof(layout::RayRecord));
  gpu::Buffer shadowHits = storage(d, "shadow hits", bandRays * frame.slotsPerRay * sizeof(layout::HitRecord));
  gpu::Buffer contributions = storage(d, "light contributions", bandRays * frame.slotsPerRay * 16);
  gpu::Buffer aovs = storage(d, "AOVs", bandPixels * sizeof(layout::PixelAovs), BufferUsage::CopySrc);
  gpu::Buffer rayRadiance = storage(d, "camera ray radiance", bandRays * 16);
  gpu::Buffer beauty = storage(d, "beauty", bandPixels * 16, BufferUsage::CopySrc);
  gpu::Buffer counters = storage(d, "shadow ray counter", 16, BufferUsage::CopyDst | BufferUsage::CopySrc);
  gpu::Buffer aovsHost = d.createBuffer({"AOVs readback", aovs.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  gpu::Buffer beautyHost =
      d.createBuffer({"beauty readback", beauty.size(), BufferUsage::MapRead | BufferUsage::CopyDst});
  gpu::Buffer countersHost = d.createBuffer({"counter readback", 16, BufferUsage::MapRead | BufferUsage::CopyDst});
  gpu::QuerySet timestamps = d.createQuerySet({"stage timestamps", 2 * kStageCount});

  auto bindGroup = [&](gpu::ComputePipeline& p, const char* label, std::vector<gpu::BindGroupEntry> entries) {
    gpu::BindGroupLayout groupLayout = p.getBindGroupLayout(0);
    return d.createBindGroup({label, &groupLayout, std::move(entries)});
  };
  // Bindings 0-4 (scene_bindings.glsl) followed by a kernel's own.
  auto withScene = [&](std::initializer_list<gpu::BindGroupEntry> own) {
    std::vector<gpu::BindGroupEntry> entries{
        {0, &frameBuffer}, {1, &nodes}, {2, &patches}, {3, &points}, {4, &objects}};
    entries.insert(entries.end(), own);
    return entries;
  };
  const std::vector<gpu::ConstantEntry> methodConstant{{"METHOD", method}};
  const double environmentMethod = !scene.environment                                       ? 0
                                   : scene.environment->method == scene::IblMethod::Sampled ? 1
                                                                                            : 2;
  gpu::ComputePipeline& raygen = pipeline("raygen", {});
  gpu::ComputePipeline& intersect = pipeline("intersect", methodConstant);
  gpu::ComputePipeline& surface =
      pipeline("surface", {{"METHOD", method},
                           {"LIGHT_COUNT", double(lightCount)},
                           {"ENVIRONMENT", environmentMethod},
                           {"OCCLUSION", scene.environment && scene.environment->occlusion ? 1.0 : 0.0},
                           {"D_MODEL", sharedModel(scene, &materials::Material::distribution)},
                           {"G_MODEL", sharedModel(scene, &materials::Material::geometry)},
                           {"F_MODEL", sharedModel(scene, &materials::Material::fresnel)}});
  gpu::ComputePipeline& gather = pipeline("gather", {});
  gpu::ComputePipeline& resolve = pipeline("resolve", {});
  gpu::BindGroup raygenGroup = bindGroup(raygen, "raygen", {{0, &frameBuffer}, {8, &rays}});
  auto intersectGroup = [&](const char* label, gpu::Buffer& rayBuffer, gpu::Buffer& hitBuffer, gpu::Buffer& count) {
    return bindGroup(intersect, label,
                     withScene({{5, &gridVertices},
                                {6, &edgeMidpoints},
                                {7, &rowBounds},
                                {8, &rayBuffer},
                                {9, &hitBuffer},
                                {10, &count}}));
  };
  gpu::BindGroup primaryGroup = intersectGroup("intersect camera rays", rays, hits, primaryCount);
  gpu::BindGroup shadowGroup = intersectGroup("intersect shadow rays", shadowRays, shadowHits, shadowCount);
  gpu::BindGroup surfaceGroup = bindGroup(surface, "surface",
                                          withScene({{8, &rays},
                                                     {9, &hits},
                                                     {11, &materialBuffer},
                                                     {12, &lightBuffer},
                                                     {13, &aovs},
                                                     {14, &shadowRays},
                                                     {15, &contributions},
                                                     {16, &counters},
                                                     {19, &texelBuffer},
                                                     {20, &levelBuffer},
                                                     {21, &aliasBuffer},
                                                     {23, &tableBuffer}}));
  gpu::BindGroup gatherGroup = bindGroup(
      gather, "gather", {{0, &frameBuffer}, {9, &hits}, {15, &contributions}, {17, &shadowHits}, {22, &rayRadiance}});
  gpu::BindGroup resolveGroup = bindGroup(resolve, "resolve", {{0, &frameBuffer}, {18, &beauty}, {22, &rayRadiance}});

  result.image = Image(width, height);
  double stageNs[kStageCount] = {};
  auto pass = [&](gpu::CommandEncoder& encoder, Stage stage, gpu::ComputePipeline& p, const gpu::BindGroup& group,
                  std::uint64_t invocations) {
    gpu::ComputePassEncoder computePass =
        encoder.beginComputePass({kStageNames[stage], {&timestamps, 2u * stage, 2u * stage + 1}});
    computePass.setPipeline(p);
    computePass.setBindGroup(0, group);
    const auto [x, y] = workgroups(invocations);
    computePass.dispatchWorkgroups(x, y);
  };
  auto addStageTimes = [&](std::initializer_list<Stage> stages) {
    for (Stage s : stages) {
      const std::vector<double> ns = timestamps.readTimestampsNs(2u * s, 2);
      stageNs[s] += ns[1] - ns[0];
    }
  };

  d.queue().writeBuffer(frameBuffer, 0, &frame, sizeof(frame));
  if (tessellated) {
    gpu::ComputePipeline& dice = pipeline("dice", {});
    gpu::BindGroup diceGroup =
        bindGroup(dice, "dice", withScene({{5, &gridVertices}, {6, &edgeMidpoints}, {7, &rowBounds}}));
    gpu::CommandEncoder encoder = d.createCommandEncoder({"dice"});
    pass(encoder, kDice, dice, diceGroup, arrays.patches.size());
    d.queue().submit(encoder.finish());
    d.queue().waitIdle();
    addStageTimes({kDice});
  }

  for (std::uint64_t first = 0; first < pixels; first += bandPixels) {
    const std::uint64_t count = std::min(bandPixels, pixels - first);
    frame.firstPixel = std::uint32_t(first);
    frame.pixelCount = std::uint32_t(count);
    // {ray count, any hit}: shadow rays only need to know whether something is in the way.
    const std::uint32_t primary[4] = {std::uint32_t(count * frame.raysPerPixel), 0, 0, 0};
    const std::uint32_t shadow[4] = {primary[0] * frame.slotsPerRay, 1, 0, 0};
    d.queue().writeBuffer(frameBuffer, 0, &frame, sizeof(frame));
    d.queue().writeBuffer(primaryCount, 0, primary, sizeof(primary));
    d.queue().writeBuffer(shadowCount, 0, shadow, sizeof(shadow));

    gpu::CommandEncoder encoder = d.createCommandEncoder({"render band"});
    encoder.clearBuffer(counters);
    pass(encoder, kRaygen, raygen, raygenGroup, primary[0]);
    pass(encoder, kIntersect, intersect, primaryGroup, primary[0]);
    pass(encoder, kSurface, surface, surfaceGroup, primary[0]);
    pass(encoder, kShadow, intersect, shadowGroup, shadow[0]);
    pass(encoder, kGather, gather, gatherGroup, primary[0]);
    pass(encoder, kResolve, resolve, resolveGroup, count);
    encoder.copyBufferToBuffer(aovs, 0, aovsHost, 0, count * sizeof(layout::PixelAovs));
    encoder.copyBufferToBuffer(beauty, 0, beautyHost, 0, count * 16);
    encoder.copyBufferToBuffer(counters, 0, countersHost, 0, 16);
    d.queue().submit(encoder.finish());
    d.queue().waitIdle();
    addStageTimes({kRaygen, kIntersect, kSurface, kShadow, kGather, kResolve});

    const auto pixelAovs = aovsHost.mapped<layout::PixelAovs>();
    const auto pixelBeauty = beautyHost.mapped<glm::vec4>();
    Image& image = result.image;
    for (std::uint64_t i = 0; i < count; ++i) {
      const layout::PixelAovs& a = pixelAovs[i];
      const std::size_t p = std::size_t(first + i);
      image.beauty[p] = pixelBeauty[i];
      image.depth[p] = a.depth;
      image.position[p] = {a.positionX, a.positionY, a.positionZ};
      image.geometricNormal[p] = {a.geometricX, a.geometricY, a.geometricZ};
      image.shadingNormal[p] = {a.shadingX, a.shadingY, a.shadingZ};
      image.patchId[p] = a.patchId;
      image.faceId[p] = a.faceId;
      image.uv[p] = {a.u, a.v};
    }
    result.primaryRays += primary[0];
    result.shadowRays += countersHost.mapped<std::uint32_t>()[0];
    if (progress) progress(double(first + count) / double(pixels));
  }
  for (int s = tessellated ? kDice : kRaygen; s < kStageCount; ++s)
    result.stageMilliseconds.emplace_back(kStageNames[s], stageNs[s] * 1e-6);
  return result;
}

}  // namespace facet::gpu_backend

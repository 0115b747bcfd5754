#include "engine/gpu_backend/gpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "engine/gpu_backend/band_passes.h"
#include "engine/gpu_backend/binding_table.h"
#include "engine/gpu_backend/frame_params.h"
#include "engine/gpu_backend/gpu_scene.h"
#include "engine/gpu_backend/pipeline_cache_file.h"
#include "engine/gpu_backend/prefilter_gpu.h"
#include "engine/gpu_backend/raycast_layout.h"
#include "engine/gpu_backend/render_buffers.h"
#include "engine/gpu_backend/shading_records.h"
#include "engine/gpu_backend/stage_clock.h"
#include "engine/ibl/environment_lighting.h"
#include "materials/material.h"
#include "rules/rules.h"

namespace facet::gpu_backend {

struct GpuRenderer::DicedGeometry {
  std::uint64_t key = 0;
  GeometryBuffers buffers;
  // What was packed from geometry `serial` about `origin` with `margin`, for
  // the next render of the same: the counts, the patch records and the
  // object ranges (the other arrays are on the device only).
  std::uint64_t serial = 0;
  glm::dvec3 origin{0.0};
  double margin = 0;
  bool tessellated = false;
  GpuScene shape;

  // Whether this packing serves `scene`'s render of `geometry`: the same
  // geometry, eye, margin and method, and its objects' ranges the same
  // under `scene`'s materials.
  bool serves(const scene::Scene& scene, const scene::SceneGeometry& geometry, const glm::dvec3& eye, double rootMargin,
              bool tessellatedMethod) const {
    if (geometry.serial == 0 || geometry.serial != serial || eye != origin || rootMargin != margin ||
        tessellatedMethod != tessellated || scene.objects.size() != shape.objects.size())
      return false;
    std::vector<layout::ObjectRange> ranges = shape.objects;
    for (std::size_t i = 0; i < ranges.size(); ++i) setObjectShading(ranges[i], scene, geometry, i);
    return std::memcmp(ranges.data(), shape.objects.data(), ranges.size() * sizeof(layout::ObjectRange)) == 0;
  }
};

GpuRenderer::GpuRenderer(gpu::Device& device) : device_(device), pipelines_(device) {}

namespace {

namespace layout = gpu_layout;

// Bands of pixels keep one band's buffers within this, so a frame's GPU
// arrays stay near it whatever its size (and each binding within the
// device's limit: bandPixelCount).
constexpr std::uint64_t kBandBytes = std::uint64_t(48) << 20;

ibl::EnvironmentLighting prepareEnvironment(gpu::Device& d, const scene::Scene& scene) {
  return ibl::prepareEnvironmentLighting(scene, [&](const scene::EnvironmentMap& map, const ibl::ModelPairs& models) {
    const ibl::PrefilterSettings settings;
    // Keyed by the device too: its limits decide how large a map it prefilters whole.
    return ibl::rememberedPrefilter(map, models, settings, "gpu " + d.adapterInfo().name,
                                    [&] { return prefilterOnGpu(d, map, models, settings); });
  });
}

// The dicing stage's pipelines; the micro-grid's vertices only when tessellated.
struct DiceKernels {
  gpu::ComputePipeline *grid = nullptr, *cells = nullptr, *quadtrees = nullptr, *refit = nullptr;
};

DiceKernels diceKernels(PipelineCache& pipelines, bool tessellated) {
  return {tessellated ? &pipelines.get("dice_grid", {}) : nullptr,
          &pipelines.get("dice_cells", {{"METHOD", tessellated ? 1.0 : 0.0}}), &pipelines.get("build_quadtrees", {}),
          &pipelines.get("refit_top_levels", {})};
}

// `packed` without the arrays that, once uploaded, the device alone needs.
GpuScene shapeOf(GpuScene packed) {
  packed.topNodes = {};
  packed.refitOrder = {};
  packed.headers = {};
  packed.points = {};
  packed.normals = {};
  packed.texcoords = {};
  return packed;
}

// Stage: dicing, the micro-grid and every patch's quadtree, then the top
// levels refitted to them.

void dice(gpu::Device& d, const DiceKernels& k, const GpuScene& packed, const BindingTable& table, StageClock& clock) {
  gpu::CommandEncoder encoder = d.createCommandEncoder({"dice"});
  if (k.grid)
    clock.dispatch(encoder, Pass::DiceGrid, *k.grid, bindGroup(d, *k.grid, "dice grid", table),
                   packed.gridVertices + packed.edgeMidpoints);
  clock.dispatch(encoder, Pass::DiceCells, *k.cells, bindGroup(d, *k.cells, "dice cells", table), packed.blocks);
  clock.dispatch(encoder, Pass::Quadtrees, *k.quadtrees, bindGroup(d, *k.quadtrees, "build quadtrees", table),
                 packed.patches.size());
  clock.begin(encoder, Pass::Refit, *k.refit, bindGroup(d, *k.refit, "refit top levels", table)).dispatchWorkgroups(1);
  d.queue().submit(encoder.finish());
  d.queue().waitIdle();
  clock.read(Pass::DiceGrid, Pass::Refit);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A band's rays and fallbacks added to the render's; `primaryRays` are the
// band's camera rays.
void addBandCounts(GpuRenderResult& result, const BandCounts& counts, std::uint64_t primaryRays) {
  result.primaryRays += primaryRays;
  result.shadowRays += counts.shadowRays;
  result.newtonFallbacks += counts.newtonFallbacks;
  result.raysPerBounce.resize(counts.bounces.size());
  for (std::size_t b = 0; b < counts.bounces.size(); ++b) {
    result.raysPerBounce[b].rays += counts.bounces[b].rays;
    result.raysPerBounce[b].hits += counts.bounces[b].hits;
    result.raysPerBounce[b].shadowRays += counts.bounces[b].shadowRays;
  }
}

// Stage: the render's pipeline compiles, and storing the cache file when
// any pipeline was compiled (wall clock); 0 where every pipeline was kept.
double pipelineStageMilliseconds(PipelineCache& pipelines, gpu::Device& d) {
  double milliseconds = pipelines.takeMilliseconds();
  if (pipelines.takeCompiled()) {
    const auto start = std::chrono::steady_clock::now();
    storePipelineCache(d);
    milliseconds += millisecondsSince(start);
  }
  return milliseconds;
}

}  // namespace

bool GpuRenderer::keepGeometry(const scene::Scene& scene, const scene::SceneGeometry& geometry, bool tessellated) {
  const glm::dvec3& origin = scene.camera.eye;
  const double margin = rootTolerance(scene, geometry);
  if (diced_ && diced_->serves(scene, geometry, origin, margin, tessellated)) return false;
  GpuScene packed = packScene(scene, geometry, origin, margin, tessellated);
  checkGeometryLimits(packed, device_.limits(), device_.adapterInfo().name);
  // The frame's tolerance is the margin in float (frame_params.h).
  const std::uint64_t key = geometryKey(packed, tessellated, float(margin));
  const bool diced = !diced_ || diced_->key != key;
  if (diced) diced_ = std::make_shared<DicedGeometry>(DicedGeometry{key, uploadGeometry(device_, packed)});
  diced_->serial = geometry.serial;
  diced_->origin = origin;
  diced_->margin = margin;
  diced_->tessellated = tessellated;
  diced_->shape = shapeOf(std::move(packed));
  return diced;
}

GpuRenderResult GpuRenderer::render(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                                    const std::function<void(double)>& progress, const std::optional<PixelRect>& crop) {
  const std::uint32_t strata = rules::f64::sample_strata(std::uint32_t(scene.render.samplesPerPixel));
  const bool tessellated = scene.render.method == scene::IntersectionMethod::Tessellated;
  checkFloatRange(scene, geometry);
  const glm::dvec3 origin = scene.camera.eye;
  gpu::Device& d = device_;
  GpuRenderResult result;

  // The packed geometry first, checked against the device's limits before
  // anything else takes time (its wall clock counts to the top levels).
  auto start = std::chrono::steady_clock::now();
  const bool diced = keepGeometry(scene, geometry, tessellated);
  const GpuScene& packed = diced_->shape;
  const double packMilliseconds = millisecondsSince(start);

  // Stage: the environment's tables or prefiltered maps (wall clock).
  start = std::chrono::steady_clock::now();
  std::optional<ibl::EnvironmentLighting> lighting;
  if (scene.environment) {
    lighting = prepareEnvironment(d, scene);
    result.stageMilliseconds.push_back({Stage::Environment, millisecondsSince(start)});
  }

  // Stage: the BVH's top levels and the patches, packed and uploaded unless
  // the last render diced the same geometry, and the textures unless the last
  // render's are the same (wall clock).
  start = std::chrono::steady_clock::now();
  layout::FrameParams frame = frameParams(scene, geometry, strata, packed);
  const scene::SceneFeatures features = scene::sceneFeatures(scene);
  frame.slotsPerRay = std::uint32_t(scene.lights.size()) + environmentSlots(lighting ? &*lighting : nullptr) +
                      (features.emission ? 1 : 0);
  const EnvironmentData environment = lighting ? environmentData(*lighting, frame) : EnvironmentData{};
  const ibl::CompensationTables compensation = ibl::compensationTables(scene);
  const std::vector<glm::vec4> compensationTexelData = compensationTexels(compensation, frame);
  const GeometryBuffers& geometryBuffers = diced_->buffers;
  const ShadingBuffers shadingBuffers = uploadShading(d, scene, lighting ? &*lighting : nullptr, environment,
                                                      compensation, compensationTexelData, origin);
  if (!textures_ || !scene::sameTextures(textures_->textures, scene.textures)) {
    textures_.reset();  // the old upload's memory is free before the new one's is taken
    textures_ = uploadTextures(d, scene.textures);
  }
  result.stageMilliseconds.push_back({Stage::TopLevels, packMilliseconds + millisecondsSince(start)});

  const int width = scene.render.width;
  const PixelRect window = crop.value_or(PixelRect::whole(width, scene.render.height));
  const std::uint64_t pixels = window.pixelCount();
  frame.windowX = std::uint32_t(window.x0);
  frame.windowY = std::uint32_t(window.y0);
  frame.windowWidth = std::uint32_t(window.width());
  const int bounces = scene.render.bounces;
  const std::uint64_t bandPixels = bandPixelCount({frame.raysPerPixel, frame.slotsPerRay, bounces > 0}, pixels,
                                                  kBandBytes, d.limits(), d.adapterInfo().name, bandAdvice(scene));
  // Fallbacks are rare (cells Newton leaves undecided); a band whose lists
  // overflow is rendered again with room for all.
  frame.fallbackCapacity = tessellated ? 0 : std::uint32_t(bandPixels * frame.raysPerPixel / 16 + 1024);
  BandBuffers band = allocateBands(d, bandPixels, bandPixels * frame.raysPerPixel, frame.slotsPerRay,
                                   frame.fallbackCapacity, bounces > 0);
  BindingTable table = bindingTable(geometryBuffers, shadingBuffers, *textures_, band);
  result.cells = packed.cells;

  StageClock clock(d);
  d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
  // Stage: the pipelines this render runs and no earlier one compiled, all
  // at once before the first dispatch (wall clock).
  pipelines_.defer();
  const DiceKernels diceK = diced ? diceKernels(pipelines_, tessellated) : DiceKernels{};
  const Kernels k = kernels(pipelines_, scene, features, lighting ? &*lighting : nullptr, compensation, tessellated);
  pipelines_.createDeferred();
  if (diced) dice(d, diceK, packed, table, clock);

  result.image = Image(window.width(), window.height());
  for (std::uint64_t first = 0; first < pixels;) {
    const std::uint64_t count = std::min(bandPixels, pixels - first);
    frame.firstPixel = std::uint32_t(first);
    frame.pixelCount = std::uint32_t(count);
    d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
    const BandCounts counts = traceBand(d, k, table, band, frame, bounces, count * frame.raysPerPixel, count, clock);
    const std::uint32_t needed = counts.neededFallbacks;
    if (needed > frame.fallbackCapacity) {
      frame.fallbackCapacity = needed;
      band = allocateBands(d, bandPixels, bandPixels * frame.raysPerPixel, frame.slotsPerRay, needed, bounces > 0);
      table = bindingTable(geometryBuffers, shadingBuffers, *textures_, band);
      continue;
    }
    readBand(band, first, count, origin, result.image);
    addBandCounts(result, counts, count * frame.raysPerPixel);
    first += count;
    if (progress) progress(double(first) / double(pixels));
  }
  result.gpuBytes = geometryBuffers.bytes + band.bytes;
  const double pipelineMilliseconds = pipelineStageMilliseconds(pipelines_, d);
  if (pipelineMilliseconds > 0) result.stageMilliseconds.push_back({Stage::Pipelines, pipelineMilliseconds});
  clock.report(result.stageMilliseconds);
  return result;
}

}  // namespace facet::gpu_backend

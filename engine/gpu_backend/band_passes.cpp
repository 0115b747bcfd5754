#include "engine/gpu_backend/band_passes.h"

#include <algorithm>
#include <cstddef>

#include "engine/gpu_backend/shading_records.h"
#include "materials/material.h"
#include "rules/rules.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

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

// The passes of one bounce's rays: the camera rays' (dispatched over the
// band's rays) or the continuation rays' (indirectly, over their list).
struct RayPasses {
  Pass intersect, compactFallbacks, fallbacks, resolveFallbacks, surface, compactShadowRays, shadow,
      compactShadowFallbacks, shadowFallbacks, gather;
};
constexpr RayPasses kCameraPasses{Pass::Intersect,       Pass::CompactCameraFallbacks,
                                  Pass::CameraFallbacks, Pass::ResolveCameraFallbacks,
                                  Pass::Surface,         Pass::CompactShadowRays,
                                  Pass::Shadow,          Pass::CompactShadowFallbacks,
                                  Pass::ShadowFallbacks, Pass::Gather};
constexpr RayPasses kBouncePasses{Pass::BounceIntersect,       Pass::BounceCompactFallbacks,
                                  Pass::BounceFallbacks,       Pass::BounceResolveFallbacks,
                                  Pass::BounceSurface,         Pass::BounceCompactShadowRays,
                                  Pass::BounceShadow,          Pass::BounceCompactShadowFallbacks,
                                  Pass::BounceShadowFallbacks, Pass::BounceGather};

// The surface kernel's FEATURES constant (compute/layout/surface_features.h).
double surfaceFeatures(const scene::Scene& scene, const scene::SceneFeatures& f,
                       const ibl::EnvironmentLighting* lighting, const ibl::CompensationTables& compensation,
                       bool paths) {
  const auto bit = [](bool on, int feature) { return on ? 1 << feature : 0; };
  return bit(scene.environment && scene.environment->occlusion, layout::FACET_FEATURE_OCCLUSION) |
         bit(lighting && lighting->environmentSamples, layout::FACET_FEATURE_ENVIRONMENT_SAMPLES) |
         bit(f.textures, layout::FACET_FEATURE_TEXTURES) | bit(f.emission, layout::FACET_FEATURE_EMISSION) |
         bit(!compensation.tables.empty(), layout::FACET_FEATURE_COMPENSATION) |
         bit(paths, layout::FACET_FEATURE_PATHS) | bit(f.transmission, layout::FACET_FEATURE_TRANSMISSION) |
         bit(paths && f.lobeLimits, layout::FACET_FEATURE_LOBE_LIMITS) |
         bit(f.anisotropy, layout::FACET_FEATURE_ANISOTROPY) | bit(f.clearcoat, layout::FACET_FEATURE_CLEARCOAT) |
         bit(f.sheen, layout::FACET_FEATURE_SHEEN) | bit(f.channels, layout::FACET_FEATURE_CHANNELS) |
         bit(f.shadowCatcher, layout::FACET_FEATURE_SHADOW_CATCHER) | bit(f.holdout, layout::FACET_FEATURE_HOLDOUT) |
         bit(f.iridescence, layout::FACET_FEATURE_IRIDESCENCE);
}

}  // namespace

Kernels kernels(PipelineCache& pipelines, const scene::Scene& scene, const scene::SceneFeatures& features,
                const ibl::EnvironmentLighting* lighting, const ibl::CompensationTables& compensation,
                bool tessellated) {
  // A constant a scene's features leave at its default is not set, so that
  // a scene without the feature runs the kernel it always ran.
  const auto feature = [](std::vector<gpu::ConstantEntry>& constants, bool on, const char* name) {
    if (on) constants.push_back({name, 1});
  };
  std::vector<gpu::ConstantEntry> method{{"METHOD", tessellated ? 1.0 : 0.0}};
  std::vector<gpu::ConstantEntry> cameraFallback{{"SHADOW", 0}}, shadowFallback{{"SHADOW", 1}};
  for (auto* constants : {&method, &cameraFallback, &shadowFallback}) {
    feature(*constants, features.culling, "CULLING");
    // 2: some object blends, and the kernels draw each ray's key (hit_filter.glsl).
    if (features.cutouts) constants->push_back({"CUTOUTS", features.blends ? 2.0 : 1.0});
  }
  auto surface = [&](bool paths) {
    return std::vector<gpu::ConstantEntry>{
        {"LIGHT_COUNT", double(scene.lights.size())},
        {"ENVIRONMENT", environmentMethod(scene)},
        {"D_MODEL", sharedModel(scene, &materials::Material::distribution)},
        {"G_MODEL", sharedModel(scene, &materials::Material::geometry)},
        {"F_MODEL", sharedModel(scene, &materials::Material::fresnel)},
        {"FEATURES", surfaceFeatures(scene, features, lighting, compensation, paths)}};
  };
  // With paths every ray's vertex, the camera ray's too, keeps a path state,
  // so one surface variant shades them all.
  Kernels k{&pipelines.get("intersect", method), &pipelines.get("surface", surface(features.paths)),
            &pipelines.get("dispatch_args", {}), &pipelines.get("shadow", method),
            &pipelines.get("gather", {}),        &pipelines.get("resolve", {})};
  if (!tessellated) {
    k.cameraFallbacks = &pipelines.get("fallback", cameraFallback);
    k.resolveCameraFallbacks = &pipelines.get("fallback_resolve", {});
    k.shadowFallbacks = &pipelines.get("fallback", shadowFallback);
  }
  if (!features.paths) return k;
  std::vector<gpu::ConstantEntry> pathIntersect = method, continuation, pathGather{{"PATHS", 1}};
  pathIntersect.push_back({"PATHS", 1});
  // A continuation ray that leaves a transmissive surface passes over it (hit_filter.glsl).
  feature(pathIntersect, features.transmission, "CROSSINGS");
  feature(continuation, features.transmission, "TRANSMISSION");
  feature(continuation, features.lobeLimits, "LOBE_LIMITS");
  feature(pathGather, features.transmission, "TRANSMISSION");
  k.continuePaths = &pipelines.get("continue_paths", continuation);
  k.pathIntersect = &pipelines.get("intersect", pathIntersect);
  k.pathGather = &pipelines.get("gather", pathGather);
  cameraFallback.push_back({"PATHS", 1});
  feature(cameraFallback, features.transmission, "CROSSINGS");
  if (!tessellated) k.pathFallbacks = &pipelines.get("fallback", cameraFallback);
  return k;
}

namespace {

// The passes of one band as command buffers: a pass over the band's camera
// rays or over a list, one bounce's rays from intersection to gather, the
// resolve, and a submit that returns the counters.
class BandEncoder {
 public:
  BandEncoder(gpu::Device& d, const Kernels& k, const BindingTable& table, BandBuffers& band, std::uint64_t rays,
              std::uint64_t pixels, StageClock& clock)
      : d_(d), k_(k), table_(table), band_(band), rays_(rays), pixels_(pixels), clock_(clock),
        dispatchArgs_(group(k.dispatchArgs, "dispatch args")) {}

  // The workgroup grids of the lists from their lengths so far.
  void compact(gpu::CommandEncoder& encoder, Pass pass) {
    clock_.begin(encoder, pass, *k_.dispatchArgs, dispatchArgs_).dispatchWorkgroups(1);
  }

  // A pass over the band's camera rays, or with `indirect` over the list
  // whose grid the counters hold at offset `list`.
  void pass(gpu::CommandEncoder& encoder, Pass pass, const gpu::ComputePipeline* p, const char* label,
            std::size_t list, bool indirect) {
    if (indirect)
      clock_.begin(encoder, pass, *p, group(p, label)).dispatchWorkgroupsIndirect(band_.counters, list);
    else
      clock_.dispatch(encoder, pass, *p, group(p, label), rays_);
  }

  // One bounce's rays from their intersection to their gather: the camera
  // rays (continuation false) or the continuation rays of the list.
  void traceRays(gpu::CommandEncoder& encoder, const RayPasses& passes, bool continuation) {
    const std::size_t pathList = offsetof(layout::RenderCounters, pathX);
    pass(encoder, passes.intersect, continuation ? k_.pathIntersect : k_.intersect, "intersect", pathList,
         continuation);
    if (k_.cameraFallbacks) {
      compact(encoder, passes.compactFallbacks);
      const std::size_t fallbacks = offsetof(layout::RenderCounters, cameraFallbackX);
      pass(encoder, passes.fallbacks, continuation ? k_.pathFallbacks : k_.cameraFallbacks, "ray fallbacks",
           fallbacks, true);
      pass(encoder, passes.resolveFallbacks, k_.resolveCameraFallbacks, "resolve fallbacks", fallbacks, true);
    }
    pass(encoder, passes.surface, k_.surface, "surface", pathList, continuation);
    compact(encoder, passes.compactShadowRays);
    pass(encoder, passes.shadow, k_.shadow, "shadow", offsetof(layout::RenderCounters, shadowX), true);
    if (k_.shadowFallbacks) {
      compact(encoder, passes.compactShadowFallbacks);
      pass(encoder, passes.shadowFallbacks, k_.shadowFallbacks, "shadow ray fallbacks",
           offsetof(layout::RenderCounters, shadowFallbackX), true);
    }
    pass(encoder, passes.gather, continuation ? k_.pathGather : k_.gather, "gather", pathList, continuation);
  }

  // The band's pixels from its rays, copied for the host.
  void finish(gpu::CommandEncoder& encoder) {
    clock_.dispatch(encoder, Pass::Resolve, *k_.resolve, group(k_.resolve, "resolve"), pixels_);
    encoder.copyBufferToBuffer(band_.aovs, 0, band_.aovsHost, 0, pixels_ * sizeof(layout::PixelAovs));
    encoder.copyBufferToBuffer(band_.beauty, 0, band_.beautyHost, 0, pixels_ * 16);
  }

  layout::RenderCounters submit(gpu::CommandEncoder& encoder) {
    encoder.copyBufferToBuffer(band_.counters, 0, band_.countersHost, 0, band_.counters.size());
    d_.queue().submit(encoder.finish());
    d_.queue().waitIdle();
    return band_.countersHost.mapped<layout::RenderCounters>()[0];
  }

 private:
  gpu::BindGroup group(const gpu::ComputePipeline* p, const char* label) { return bindGroup(d_, *p, label, table_); }

  gpu::Device& d_;
  const Kernels& k_;
  const BindingTable& table_;
  BandBuffers& band_;
  std::uint64_t rays_, pixels_;
  StageClock& clock_;
  gpu::BindGroup dispatchArgs_;
};

}  // namespace

BandCounts traceBand(gpu::Device& d, const Kernels& k, const BindingTable& table, BandBuffers& band,
                     gpu_layout::FrameParams frame, int bounces, std::uint64_t rays, std::uint64_t pixels,
                     StageClock& clock) {
  BandEncoder passes(d, k, table, band, rays, pixels, clock);
  BandCounts counts;
  auto add = [&](const layout::RenderCounters& c) {
    counts.shadowRays += c.shadowRays;
    counts.newtonFallbacks += c.cameraFallbacks + c.shadowFallbacks;
    counts.neededFallbacks = std::max({counts.neededFallbacks, c.cameraFallbacks, c.shadowFallbacks});
    return counts.neededFallbacks <= frame.fallbackCapacity;
  };

  gpu::CommandEncoder encoder = d.createCommandEncoder({"render band"});
  encoder.clearBuffer(band.counters);
  passes.traceRays(encoder, kCameraPasses, false);
  if (bounces == 0) passes.finish(encoder);
  const layout::RenderCounters camera = passes.submit(encoder);
  clock.read(Pass::Intersect, Pass::Resolve);
  if (!add(camera) || bounces == 0) return counts;
  counts.bounces.push_back({rays, camera.pathHits, camera.shadowRays});

  // Paths: one submit per bounce, its frame naming the vertex the
  // continuation rays leave and the seed of the vertex they hit. A bounce
  // continues the live list the last one appended (its counters are kept
  // when the others are cleared), then starts its own.
  const std::size_t liveCount = offsetof(layout::RenderCounters, livePaths);
  const std::uint32_t seed = frame.environmentSeed;
  frame.pathSeed = seed;
  std::uint64_t alive = camera.livePaths;
  int bounce = 1;
  bool complete = true;  // false: a fallback list overflowed, and the band is rendered again with room
  for (; bounce <= bounces && alive > 0 && complete; ++bounce) {
    frame.pathVertex = std::uint32_t(bounce);
    frame.environmentSeed = rules::f32::path_vertex_seed(seed, std::uint32_t(bounce) + 1);
    d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
    gpu::CommandEncoder bounceEncoder = d.createCommandEncoder({"render band's bounce"});
    bounceEncoder.clearBuffer(band.counters, 0, liveCount);
    passes.pass(bounceEncoder, Pass::Continue, k.continuePaths, "continue paths",
                offsetof(layout::RenderCounters, liveX), true);
    bounceEncoder.clearBuffer(band.counters, liveCount, sizeof(std::uint32_t));
    passes.compact(bounceEncoder, Pass::BounceCompact);
    passes.traceRays(bounceEncoder, kBouncePasses, true);
    if (bounce == bounces) passes.finish(bounceEncoder);
    const layout::RenderCounters c = passes.submit(bounceEncoder);
    clock.read(Pass::Continue, Pass::BounceGather);
    counts.bounces.push_back({c.pathRays, c.pathHits, c.shadowRays});
    alive = c.livePaths;
    complete = add(c);
  }
  if (complete && bounce <= bounces) {
    // Every path ended early: the bounces left trace nothing.
    counts.bounces.resize(std::size_t(bounces) + 1);
    gpu::CommandEncoder finishEncoder = d.createCommandEncoder({"render band's resolve"});
    passes.finish(finishEncoder);
    passes.submit(finishEncoder);
  }
  clock.read(Pass::Resolve, Pass::Resolve);
  // The next band's camera rays read the scene's seed again.
  frame.pathVertex = 0;
  frame.environmentSeed = seed;
  d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
  return counts;
}

}  // namespace facet::gpu_backend

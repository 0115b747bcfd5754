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
         bit(f.sheen, layout::FACET_FEATURE_SHEEN) | bit(f.channels, layout::FACET_FEATURE_CHANNELS);
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
    feature(*constants, features.cutouts, "CUTOUTS");
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
  feature(continuation, features.transmission, "TRANSMISSION");
  feature(continuation, features.lobeLimits, "LOBE_LIMITS");
  feature(pathGather, features.transmission, "TRANSMISSION");
  k.continuePaths = &pipelines.get("continue_paths", continuation);
  k.pathIntersect = &pipelines.get("intersect", pathIntersect);
  k.pathGather = &pipelines.get("gather", pathGather);
  cameraFallback.push_back({"PATHS", 1});
  if (!tessellated) k.pathFallbacks = &pipelines.get("fallback", cameraFallback);
  return k;
}

BandCounts traceBand(gpu::Device& d, const Kernels& k, const BindingTable& table, BandBuffers& band,
                     gpu_layout::FrameParams frame, int bounces, std::uint64_t rays, std::uint64_t pixels,
                     StageClock& clock) {
  auto group = [&](const gpu::ComputePipeline* p, const char* label) { return bindGroup(d, *p, label, table); };
  const gpu::BindGroup dispatchArgs = group(k.dispatchArgs, "dispatch args");
  auto compact = [&](Pass pass, gpu::CommandEncoder& encoder) {
    clock.begin(encoder, pass, *k.dispatchArgs, dispatchArgs).dispatchWorkgroups(1);
  };
  // A pass over the band's camera rays, or with `list` indirectly over a
  // list whose grid the counters hold at that offset.
  auto pass = [&](gpu::CommandEncoder& encoder, Pass pass, const gpu::ComputePipeline* p, const char* label,
                  std::size_t list, bool indirect) {
    if (indirect)
      clock.begin(encoder, pass, *p, group(p, label)).dispatchWorkgroupsIndirect(band.counters, list);
    else
      clock.dispatch(encoder, pass, *p, group(p, label), rays);
  };
  const std::size_t pathList = offsetof(layout::RenderCounters, pathX);
  // One bounce's rays from their intersection to their gather: the camera
  // rays (continuation false) or the continuation rays of the list.
  auto traceRays = [&](gpu::CommandEncoder& encoder, const RayPasses& passes, bool continuation) {
    pass(encoder, passes.intersect, continuation ? k.pathIntersect : k.intersect, "intersect", pathList, continuation);
    if (k.cameraFallbacks) {
      compact(passes.compactFallbacks, encoder);
      const std::size_t fallbacks = offsetof(layout::RenderCounters, cameraFallbackX);
      pass(encoder, passes.fallbacks, continuation ? k.pathFallbacks : k.cameraFallbacks, "ray fallbacks", fallbacks,
           true);
      pass(encoder, passes.resolveFallbacks, k.resolveCameraFallbacks, "resolve fallbacks", fallbacks, true);
    }
    pass(encoder, passes.surface, k.surface, "surface", pathList, continuation);
    compact(passes.compactShadowRays, encoder);
    pass(encoder, passes.shadow, k.shadow, "shadow", offsetof(layout::RenderCounters, shadowX), true);
    if (k.shadowFallbacks) {
      compact(passes.compactShadowFallbacks, encoder);
      pass(encoder, passes.shadowFallbacks, k.shadowFallbacks, "shadow ray fallbacks",
           offsetof(layout::RenderCounters, shadowFallbackX), true);
    }
    pass(encoder, passes.gather, continuation ? k.pathGather : k.gather, "gather", pathList, continuation);
  };
  auto finish = [&](gpu::CommandEncoder& encoder) {
    clock.dispatch(encoder, Pass::Resolve, *k.resolve, group(k.resolve, "resolve"), pixels);
    encoder.copyBufferToBuffer(band.aovs, 0, band.aovsHost, 0, pixels * sizeof(layout::PixelAovs));
    encoder.copyBufferToBuffer(band.beauty, 0, band.beautyHost, 0, pixels * 16);
  };
  auto submit = [&](gpu::CommandEncoder& encoder) {
    encoder.copyBufferToBuffer(band.counters, 0, band.countersHost, 0, band.counters.size());
    d.queue().submit(encoder.finish());
    d.queue().waitIdle();
    return band.countersHost.mapped<layout::RenderCounters>()[0];
  };

  BandCounts counts;
  auto add = [&](const layout::RenderCounters& c) {
    counts.shadowRays += c.shadowRays;
    counts.newtonFallbacks += c.cameraFallbacks + c.shadowFallbacks;
    counts.neededFallbacks = std::max({counts.neededFallbacks, c.cameraFallbacks, c.shadowFallbacks});
    return counts.neededFallbacks <= frame.fallbackCapacity;
  };

  gpu::CommandEncoder encoder = d.createCommandEncoder({"render band"});
  encoder.clearBuffer(band.counters);
  traceRays(encoder, kCameraPasses, false);
  if (bounces == 0) finish(encoder);
  const layout::RenderCounters camera = submit(encoder);
  clock.read(Pass::Intersect, Pass::Resolve);
  if (!add(camera) || bounces == 0) return counts;
  counts.bounces.push_back({rays, camera.pathHits, camera.shadowRays});

  // Paths: one submit per bounce, its frame naming the vertex the
  // continuation rays leave and the seed of the vertex they hit.
  const std::uint32_t seed = frame.environmentSeed;
  frame.pathSeed = seed;
  std::uint64_t alive = camera.pathHits;
  for (int bounce = 1; bounce <= bounces; ++bounce) {
    frame.pathVertex = std::uint32_t(bounce);
    frame.environmentSeed = rules::f32::path_vertex_seed(seed, std::uint32_t(bounce) + 1);
    d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
    gpu::CommandEncoder bounceEncoder = d.createCommandEncoder({"render band's bounce"});
    bounceEncoder.clearBuffer(band.counters);
    if (alive > 0) {
      pass(bounceEncoder, Pass::Continue, k.continuePaths, "continue paths", 0, false);
      compact(Pass::BounceCompact, bounceEncoder);
      traceRays(bounceEncoder, kBouncePasses, true);
    }
    if (bounce == bounces) finish(bounceEncoder);
    const layout::RenderCounters c = submit(bounceEncoder);
    clock.read(Pass::Continue, Pass::BounceGather);
    counts.bounces.push_back({c.pathRays, c.pathHits, c.shadowRays});
    alive = c.pathHits;
    if (!add(c)) break;
  }
  clock.read(Pass::Resolve, Pass::Resolve);
  // The next band's camera rays read the scene's seed again.
  frame.pathVertex = 0;
  frame.environmentSeed = seed;
  d.queue().writeBuffer(band.frame, 0, &frame, sizeof(frame));
  return counts;
}

}  // namespace facet::gpu_backend

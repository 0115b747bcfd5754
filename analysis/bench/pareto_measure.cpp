#include "analysis/bench/pareto_measure.h"

#if FACET_HAVE_EMBREE
#include "analysis/peers/embree_peer.h"
#endif

namespace facet::analysis::bench::pareto {
namespace {

void apply(const Setting& s, scene::Scene& scene) {
  if (s.method == "exact") {
    scene.render.method = scene::IntersectionMethod::Exact;
    scene.render.exactTolerance = s.value;
  } else if (s.method == "tessellated") {
    scene.render.method = scene::IntersectionMethod::Tessellated;
    scene.render.tessellationRate = int(s.value);
  } else if (s.method == "sampled") {
    scene.environment->method = scene::IblMethod::Sampled;
    scene.environment->samples = int(s.value);
  } else if (s.method == "prefiltered") {
    scene.environment->method = scene::IblMethod::Prefiltered;
  }
}

}  // namespace

RenderReport renderReference(Renderer& renderer, const Scenario& s) {
  scene::Scene reference = s.scene;
  reference.render.method = scene::IntersectionMethod::Exact;
  reference.render.exactTolerance.reset();
  if (s.referenceSamples > 0) {
    reference.environment->method = scene::IblMethod::Sampled;
    reference.environment->samples = s.referenceSamples;
  }
  return renderer.render(reference, Backend::Cpu);
}

Point measure(Renderer& renderer, const Scenario& s, const Setting& setting, Backend backend, const Image& reference,
              const BenchOptions& options) {
  scene::Scene scene = s.scene;
  apply(setting, scene);
  // Untimed: compiles the GPU pipeline variant and fills the environment's
  // caches; its image is the one compared.
  RenderReport first = renderer.render(scene, backend);
  Point p{backend == Backend::Gpu ? "gpu" : "cpu", setting, 0, compareToReference(first.image, reference),
          std::move(first.image)};
  p.milliseconds =
      medianMilliseconds(options.repeats, [&] { return traceMilliseconds(renderer.render(scene, backend)); });
  return p;
}

#if FACET_HAVE_EMBREE
EmbreeRun measureEmbree(const Scenario& s, const Sizes& sizes, const Image& reference, const BenchOptions& options) {
  constexpr int kThreads = 2;  // the machine's cores, as lavapipe and the CPU reference use
  peers::EmbreeSubdivision embree(s.scene.objects.front().cage, kThreads);
  const int width = s.scene.render.width, height = s.scene.render.height;
  EmbreeRun run{{}, embree.notes()};
  for (int rate : sizes.embreeRates) {
    embree.setTessellationRate(rate);
    std::vector<float> depth;
    embree.castPrimary(s.scene.camera, width, height, depth);
    Image candidate(width, height);
    for (std::size_t i = 0; i < depth.size(); ++i) {
      candidate.shadingNormal[i] = reference.shadingNormal[i];
      if (!covered(depth[i])) continue;
      candidate.depth[i] = depth[i];
      candidate.beauty[i].a = 1;
      candidate.patchId[i] = 0;  // a hit: Embree names no facet patch
    }
    Point p{"embree", {"tessellated", "rate", double(rate)}, 0, compareToReference(candidate, reference), {}};
    p.milliseconds =
        medianMilliseconds(options.repeats, [&] { return embree.castPrimary(s.scene.camera, width, height, depth); });
    run.points.push_back(std::move(p));
  }
  return run;
}
#endif

}  // namespace facet::analysis::bench::pareto

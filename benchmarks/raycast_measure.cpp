#include "benchmarks/raycast_measure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/image_compare.h"
#include "benchmarks/wall_clock.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

#if FACET_HAVE_EMBREE
#include "analysis/peers/embree_peer.h"
#endif

namespace facet::benchmarks::raycast {
namespace {

using facet::RenderReport;
using facet::analysis::compareDepth;
using facet::analysis::DepthError;
using facet::scene::IntersectionMethod;
using facet::scene::Scene;

Row runFacet(facet::Renderer& renderer, const NamedCage& cage, const Scene& scene, facet::Backend backend,
             std::vector<float>* depthOut) {
  const RenderReport report = renderer.render(scene, backend);
  Row row;
  row.cage = cage.name;
  row.patches = report.patches;
  row.size = scene.render.width;
  row.engine = backend == facet::Backend::Gpu ? "facet-gpu" : "facet-cpu";
  if (scene.render.method == IntersectionMethod::Exact) {
    row.method = "exact";
  } else {
    const auto choice = facet::scene::chooseRefinement(scene.objects[0], scene.camera, scene.render);
    row.method = "tess k=" + std::to_string(scene.render.tessellationRate.value_or(choice.tessellationRate));
  }
  row.primaryRays = report.primaryRays;
  row.shadowRays = report.shadowRays;
  row.traceMs = 0;
  double primary = 0;  // GPU: camera rays generated and intersected, fallbacks included (Embree's loop does both too)
  for (const auto& stage : report.stages) {
    row.stages += std::string(stageName(stage.stage)) + "=" + fmt(stage.milliseconds, "%.2f") + ";";
    if (stage.stage == Stage::RefineBvh) {
      row.refineMs = stage.milliseconds;
      continue;
    }
    if (isStartup(stage.stage)) continue;
    row.traceMs += stage.milliseconds;
    if (stage.stage == Stage::Intersect || stage.stage == Stage::Fallbacks) primary += stage.milliseconds;
    if (stage.stage == Stage::ShadowRays || stage.stage == Stage::ShadowFallbacks)
      row.shadowMs = (std::isnan(row.shadowMs) ? 0 : row.shadowMs) + stage.milliseconds;
  }
  if (primary > 0) row.primaryMs = primary;
  if (depthOut) *depthOut = report.image.depth;
  return row;
}

// Warm-up: compile every GPU pipeline once outside the timed renders.
void warmUp(facet::Renderer& renderer, const NamedCage& cage) {
  Scene warm = facet::scene::sceneFromCage(cage.cage);
  warm.render.width = warm.render.height = 32;
  for (IntersectionMethod m : {IntersectionMethod::Exact, IntersectionMethod::Tessellated}) {
    warm.render.method = m;
    (void)renderer.render(warm, facet::Backend::Gpu);
  }
}

// The CPU exact method is the slow oracle; it would be skipped where it
// dominates the run (said in the output); no cage here is that large.
bool skipCpuExact(const NamedCage& c, int size) { return size >= 1024 && c.cage.faceCount() > 1000000; }

// facet's four rows of `scene`: exact and tessellated on each backend, their
// depth against the CPU exact one's, which becomes `referenceDepth` (empty
// where it is skipped).
void addFacetRows(std::vector<Row>& rows, std::vector<std::string>& skipped, facet::Renderer& renderer,
                  const NamedCage& cage, Scene& scene, std::vector<float>& referenceDepth) {
  const int size = scene.render.width;
  scene.render.method = IntersectionMethod::Exact;
  if (skipCpuExact(cage, size)) {
    skipped.push_back("CPU exact skipped on " + cage.name + " at " + std::to_string(size) +
                      "² (too slow for the time budget); no depth errors there");
  } else {
    Row row = runFacet(renderer, cage, scene, facet::Backend::Cpu, &referenceDepth);
    row.error = compareDepth(referenceDepth, referenceDepth);
    rows.push_back(row);
  }
  std::vector<float> depth;
  Row gpuExact = runFacet(renderer, cage, scene, facet::Backend::Gpu, &depth);
  gpuExact.error = compareDepth(depth, referenceDepth);
  rows.push_back(gpuExact);

  scene.render.method = IntersectionMethod::Tessellated;
  Row cpuTess = runFacet(renderer, cage, scene, facet::Backend::Cpu, &depth);
  cpuTess.error = compareDepth(depth, referenceDepth);
  rows.push_back(cpuTess);
  Row gpuTess = runFacet(renderer, cage, scene, facet::Backend::Gpu, &depth);
  gpuTess.error = compareDepth(depth, referenceDepth);
  rows.push_back(gpuTess);
}

}  // namespace

Measurements measureAll(Renderer& renderer, const std::vector<NamedCage>& cages, const std::vector<int>& sizes,
                        [[maybe_unused]] const std::vector<int>& allRates, [[maybe_unused]] bool quick) {
  // Faces × rate² grid quads, about 2 GB: Embree's rates past it are left out.
  [[maybe_unused]] constexpr double kEmbreeGridBudget = 40e6;
  const double runStart = nowMs();
  std::vector<Row> rows;
  std::vector<std::string> skipped;
  std::vector<std::string> checks;  // --quick: embree8's depth against embree's
  bool checksPassed = true;

  warmUp(renderer, cages[0]);

  for (const NamedCage& cage : cages) {
#if FACET_HAVE_EMBREE
    facet::peers::EmbreeSubdivision embree(cage.cage, kThreads);
    std::vector<int> rates;
    for (int rate : allRates)
      if (double(cage.cage.faceCount()) * rate * rate <= kEmbreeGridBudget) rates.push_back(rate);
    if (rates.size() < allRates.size())
      skipped.push_back("Embree rates above " + std::to_string(rates.back()) + " skipped on " + cage.name +
                        " (faces × rate² > 40M grid quads)");
    std::vector<double> commitMs(rates.size());
#endif
    for (int size : sizes) {
      Scene scene = facet::scene::sceneFromCage(cage.cage);
      scene.render.width = scene.render.height = size;
      std::vector<float> referenceDepth;
      std::fprintf(stderr, "[%6.1f s] %s %d²\n", (nowMs() - runStart) / 1e3, cage.name.c_str(), size);

      addFacetRows(rows, skipped, renderer, cage, scene, referenceDepth);

#if FACET_HAVE_EMBREE
      // Median of 3 casts by `cast` into `out`, as a row of `engine`.
      using Cast =
          double (facet::peers::EmbreeSubdivision::*)(const facet::scene::Camera&, int, int, std::vector<float>&) const;
      auto embreeRow = [&](const std::string& engine, Cast cast, double commit, int rate, std::vector<float>& out) {
        std::vector<double> times;
        for (int rep = 0; rep < 3; ++rep) times.push_back((embree.*cast)(scene.camera, size, size, out));
        std::sort(times.begin(), times.end());
        Row row;
        row.cage = cage.name;
        row.patches = cage.cage.faceCount();
        row.size = size;
        row.engine = engine;
        row.method = "rate=" + std::to_string(rate);
        row.refineMs = commit;
        row.primaryMs = times[1];
        row.traceMs = times[1];
        row.primaryRays = std::uint64_t(size) * std::uint64_t(size);
        row.error = compareDepth(out, referenceDepth);
        row.stages = "commit=" + fmt(commit, "%.2f") + ";intersect(median of 3)=" + fmt(times[1], "%.2f") + ";";
        row.note = embree.notes();
        return row;
      };
      std::vector<float> depth, depth8;
      for (std::size_t r = 0; r < rates.size(); ++r) {
        commitMs[r] = embree.setTessellationRate(rates[r]);
        rows.push_back(
            embreeRow(kEmbreeEngines[0], &facet::peers::EmbreeSubdivision::castPrimary, commitMs[r], rates[r], depth));
        rows.push_back(embreeRow(kEmbreeEngines[1], &facet::peers::EmbreeSubdivision::castPrimary8, commitMs[r],
                                 rates[r], depth8));
        if (quick) {
          // rtcIntersect8 must see what rtcIntersect1 sees: same coverage, depth to float rounding.
          const DepthError e = compareDepth(depth8, depth);
          const bool ok = e.coverageMismatch == 0 && !(e.maxRelative >= 1e-5);
          checksPassed = checksPassed && ok;
          checks.push_back("embree8 vs embree depth on " + cage.name + " " + std::to_string(size) +
                           "² rate=" + std::to_string(rates[r]) + ": max rel. diff " + fmtSci(e.maxRelative) +
                           " over " + std::to_string(e.bothCovered) + " pixels, coverage mismatch " +
                           std::to_string(e.coverageMismatch) + (ok ? ": ok" : ": FAILED (limit 1e-5, 0)"));
        }
      }
#endif
    }
  }
  const double runSeconds = (nowMs() - runStart) / 1e3;
  return {std::move(rows), std::move(skipped), std::move(checks), checksPassed, runSeconds};
}

}  // namespace facet::benchmarks::raycast

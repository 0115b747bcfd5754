// facet bench, section "pareto": per scene, every method and knob against a
// converged reference, time against error on a log-log chart with the
// non-dominated points joined, Embree 3's tessellation rates beside facet's
// methods on the torture cages.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"
#include "analysis/bench/pareto_measure.h"
#include "analysis/bench/pareto_report.h"
#include "analysis/bench/pareto_scenarios.h"

namespace facet::analysis::bench {
namespace {

namespace fs = std::filesystem;

}  // namespace

void runPareto(Renderer& renderer, const BenchOptions& options, Report& report) {
  using namespace pareto;
  const Sizes sizes = sizesFor(options.quick);
  const std::string relative = "pareto";
  const fs::path directory = options.output / relative;
  fs::create_directories(directory);

  report.heading("Speed against accuracy");
  std::string intro =
      "Per scene, every method and knob on both backends against a converged reference (CPU, exact, default "
      "ε = 1e-9 of each object's diagonal, same samples per pixel; sampled IBL with N = " +
      std::to_string(sizes.referenceSamples) + " pairs on the IBL scene). Time: the median of " +
      std::to_string(options.repeats) +
      " run(s) after an untimed one, of every stage but refinement + BVH and the environment's preparation (GPU "
      "timestamps on the GPU). Error: over pixels both images cover. The dashed line joins the non-dominated "
      "points; errors of 0 are drawn at " +
      cell(kChartFloor) + ".";
#if FACET_HAVE_EMBREE
  intro +=
      " Embree 3 (RTC_GEOMETRY_TYPE_SUBDIVISION, rtcIntersect1 on 2 threads, tessellation rate swept) casts the "
      "same camera rays at the torture cages; its time is primary rays alone (facet's also shades and casts "
      "shadow rays), its error depth alone.";
#else
  intro += " Embree 3 was not found when facet was built (Debian libembree-dev): no peer points.";
#endif
  report.paragraph(intro);

  for (const Scenario& s : scenarios(options, sizes)) {
    const RenderReport reference = renderReference(renderer, s);
    std::printf("pareto %s %dx%d: reference %.0f ms\n", s.name.c_str(), s.scene.render.width, s.scene.render.height,
                traceMilliseconds(reference));
    const double floor = gpuToleranceFloor(s.scene);
    std::vector<pareto::Point> points;
    std::vector<std::string> skipped;
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
      bool floorMeasured = false;
      for (const Setting& setting : s.settings) {
        // Below the float floor the GPU renders the floor: one point says it.
        if (backend == Backend::Gpu && setting.method == "exact" && setting.value < floor) {
          if (floorMeasured) {
            skipped.push_back(cell(setting.value));
            continue;
          }
          floorMeasured = true;
        }
        points.push_back(measure(renderer, s, setting, backend, reference.image, options));
        const pareto::Point& p = points.back();
        std::printf("  %-4s %-22s %9.1f ms  %s %.3g\n", p.backend.c_str(), p.setting.label().c_str(), p.milliseconds,
                    axisName(s.axis).c_str(), chartedError(p.error, s.axis));
        std::fflush(stdout);
      }
    }
    std::string embreeNotes;
#if FACET_HAVE_EMBREE
    if (s.embreePeer) {
      EmbreeRun run = measureEmbree(s, sizes, reference.image, options);
      embreeNotes = "; Embree: primary rays alone" + (run.notes.empty() ? "" : ", " + run.notes);
      for (pareto::Point& p : run.points) {
        std::printf("  %-4s %-22s %9.1f ms  %s %.3g\n", p.backend.c_str(), p.setting.label().c_str(), p.milliseconds,
                    axisName(s.axis).c_str(), chartedError(p.error, s.axis));
        points.push_back(std::move(p));
      }
    }
#endif
    std::string subtitle = std::to_string(s.scene.render.width) + "x" + std::to_string(s.scene.render.height) +
                           ", median of " + std::to_string(options.repeats) + "; reference: CPU exact" +
                           (s.referenceSamples > 0 ? ", sampled N=" + std::to_string(s.referenceSamples) : "");
    subtitle += embreeNotes;
    if (!skipped.empty()) {
      subtitle += "; GPU exact below its float floor ε ≈ " + threeDigits(floor) + " not run (";
      for (std::size_t i = 0; i < skipped.size(); ++i) subtitle += (i ? ", " : "") + skipped[i];
      subtitle += ": the same render as the first below it)";
    }
    const bool hasExact = std::any_of(s.settings.begin(), s.settings.end(),
                                      [](const Setting& setting) { return setting.method == "exact"; });
    const std::string floorNote =
        hasExact ? "The GPU's exact method accepts roots within at least ε ≈ " + threeDigits(floor) +
                       " of the diagonal here (8 float ulps of the largest coordinate); below that its renders do "
                       "not change."
                 : "";
    reportScenario(s, points, reference.image, directory, relative, subtitle, floorNote, report);
  }
}

}  // namespace facet::analysis::bench

// Rendering and parity through the engine's Renderer.
#include "facet/render.h"

#include <tuple>

#include "analysis/parity.h"
#include "analysis/parity_run.h"
#include "api/errors.h"
#include "api/image_planes.h"
#include "api/render_settings.h"
#include "api/renderer_state.h"
#include "api/scene_data.h"
#include "engine/adaptive_render.h"
#include "engine/image_memory.h"
#include "engine/renderer.h"
#include "facet/version.h"
#include "scenes/input_error.h"
#include "scenes/light_transport.h"

namespace facet::v0 {

const Aov& Image::aov(const std::string& name) const {
  const auto found = aovs.find(name);
  if (found == aovs.end()) throw Error(ErrorKind::BadInput, "image: no AOV named '" + name + "'");
  return found->second;
}

Renderer::Renderer(const std::string& adapter) : state_(std::make_unique<State>(adapter)) {}
Renderer::~Renderer() = default;

RenderResult Renderer::render(const Scene& input, const RenderSettings& settings) {
  return api::translateErrors([&] {
    const std::scoped_lock oneAtATime(state_->rendering);
    const scene::Scene s = withSettings(input, settings);
    checkImagesFitInMemory(s, 1, "render settings: width x height");
    const facet::Backend backend = settings.backend == Backend::Cpu ? facet::Backend::Cpu : facet::Backend::Gpu;
    AdaptiveReport rounds;
    const RenderReport report = renderPicture(state_->engine, s, backend, {}, {}, kNoTimeLimit, &rounds);
    RenderResult result{publicImage(report.image),          report.device,
                        report.totalMilliseconds(),         report.lightTransport.bounces,
                        report.lightTransport.note,         {},
                        api::samplingReport(report, rounds)};
    for (const cpu::BounceRays& rays : report.raysPerBounce)
      result.raysPerBounce.push_back({rays.rays, rays.hits, rays.shadowRays});
    return result;
  });
}

ParityReport Renderer::parity(const Scene& input, const RenderSettings& settings, const ParityOptions& options) {
  return api::translateErrors([&] {
    if (options.renders < 1 || options.renders > 1024)
      api::refuse("parity options", "renders", "expected renders per backend in [1, 1024]");
    const analysis::ParityTolerances tolerances =
        analysis::parityTolerances(options.tolerances, options.minCoverage, "parity options: tolerances");
    const std::scoped_lock oneAtATime(state_->rendering);
    scene::Scene s = withSettings(input, settings);
    scene::leaveNothingToChoose(s);
    analysis::ParityCase judged =
        analysis::judgeParity(api::kCodeSource, std::move(s), {{&state_->engine, "gpu", {}}}, state_->engine,
                              options.renders, tolerances, "render settings: width x height");
    // The run is named by the device that rendered it, as the command line names its adapter.
    judged.runs.front().adapter = judged.runs.front().adapterInfo.value("device", "gpu");
    const analysis::ParityReport& r = judged.runs.front().report;
    ParityReport out{r.width,
                     r.height,
                     r.covered,
                     r.coverageMismatches,
                     r.coveragePass,
                     {},
                     analysis::toString(r.verdict),
                     r.pass,
                     judged.settings["rendersPerBackend"].get<int>(),
                     analysis::describe(r),
                     analysis::parityCaseJson(judged).dump()};
    for (const analysis::AovParity& a : r.aovs) {
      const double tolerance = !a.gated ? 0 : a.tolerance.relative > 0 ? a.tolerance.relative : a.tolerance.absolute;
      out.aovs.push_back({a.name, a.gated, a.gated ? a.test : "", a.gated ? analysis::passRule(a) : "", a.maxRelative,
                          a.meanRelative, tolerance, a.shareOver, a.over(), a.allowed, a.minPValue, a.pass});
    }
    return out;
  });
}

const char* version() { return FACET_VERSION_STRING; }

}  // namespace facet::v0

namespace facet::api {

v0::SamplingReport samplingReport(const RenderReport& report, const AdaptiveReport& rounds) {
  v0::SamplingReport s;
  if (report.samplesPerPixel == 0) s = adaptiveSampling(rounds);
  s.spp = report.samplesPerPixel;
  s.why = report.samplingNote;
  return s;
}

v0::SamplingReport adaptiveSampling(const AdaptiveReport& rounds) {
  v0::SamplingReport s;
  s.rounds = rounds.rounds;
  s.sppMean = rounds.sppMean;
  std::tie(s.sppMin, s.sppMax) = tileSppRange(rounds);
  s.maxTileError = rounds.maxError;
  s.noiseThreshold = rounds.noiseThreshold;
  s.stop = toString(rounds.stop);
  return s;
}

}  // namespace facet::api

// Rendering and parity through the engine's Renderer.
#include "facet/render.h"

#include <tuple>

#include "analysis/parity.h"
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

ParityReport Renderer::parity(const Scene& input, const RenderSettings& settings) {
  return api::translateErrors([&] {
    const std::scoped_lock oneAtATime(state_->rendering);
    scene::Scene s = withSettings(input, settings);
    scene::leaveNothingToChoose(s);
    checkImagesFitInMemory(s, 2, "render settings: width x height");
    // The GPU first: it refuses what it cannot render (a scene beyond float's range) before the CPU spends a
    // render on it.
    const RenderReport gpu = state_->engine.render(s, facet::Backend::Gpu);
    const RenderReport cpu = state_->engine.render(s, facet::Backend::Cpu);
    const analysis::ParityReport r = analysis::compareImages(cpu.image, gpu.image);
    ParityReport out{r.width,        r.height, r.covered, r.coverageMismatches,
                     r.coveragePass, {},       r.pass,    analysis::describe(r)};
    // The public struct keeps one number per tolerance (docs/api.md: its layout is
    // the ABI): the relative part, or the absolute one where there is none
    // (normals); the summary states both and the pass rule.
    for (const analysis::AovParity& a : r.aovs) {
      const double tolerance = !a.gated ? 0 : a.tolerance.relative > 0 ? a.tolerance.relative : a.tolerance.absolute;
      out.aovs.push_back({a.name, a.maxRelative, a.meanRelative, tolerance, a.shareOver, a.pass});
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

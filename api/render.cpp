// Rendering and parity through the engine's Renderer, and the engine's Image
// as named AOV planes.
#include "facet/render.h"

#include <mutex>

#include "analysis/parity.h"
#include "api/errors.h"
#include "api/scene_data.h"
#include "engine/renderer.h"
#include "scenes/memory_budget.h"
#include "facet/version.h"
#include "scenes/input_error.h"

namespace facet::v0 {
namespace {

template <int N, class Plane>
Aov aov(const Plane& plane) {
  Aov out;
  out.channels = N;
  out.values.resize(plane.size() * N);
  for (std::size_t i = 0; i < plane.size(); ++i)
    for (int c = 0; c < N; ++c) out.values[i * N + std::size_t(c)] = plane[i][c];
  return out;
}

Image publicImage(const facet::Image& image) {
  Image out;
  out.width = image.width;
  out.height = image.height;
  out.aovs["beauty"] = aov<4>(image.beauty);
  out.aovs["depth"] = Aov{1, image.depth};
  out.aovs["position"] = aov<3>(image.position);
  out.aovs["geometric_normal"] = aov<3>(image.geometricNormal);
  out.aovs["shading_normal"] = aov<3>(image.shadingNormal);
  out.aovs["uv"] = aov<2>(image.uv);
  out.aovs["texcoord"] = aov<2>(image.texcoord);
  out.ids["patch_id"] = image.patchId;
  out.ids["face_id"] = image.faceId;
  return out;
}

void require(bool valid, const std::string& field, const std::string& rule) {
  if (!valid) throw scene::InputError("render settings", 0, field, rule);
}

scene::Scene withSettings(const Scene& input, const RenderSettings& s) {
  scene::Scene out = input.data().scene;
  if (s.width) require(*s.width >= 1 && *s.width <= 16384, "width", "must be in [1, 16384]");
  if (s.height) require(*s.height >= 1 && *s.height <= 16384, "height", "must be in [1, 16384]");
  if (s.samplesPerPixel)
    require(*s.samplesPerPixel >= 1 && *s.samplesPerPixel <= 4096 && scene::isSquare(*s.samplesPerPixel),
            "samplesPerPixel", std::string("must be in [1, 4096]; ") + scene::kSamplesPerPixelRule);
  if (s.tessellationRate)
    require(*s.tessellationRate >= 1 && *s.tessellationRate <= 256, "tessellationRate", "must be in [1, 256]");
  if (s.bounces)
    require(*s.bounces >= 0 && *s.bounces <= scene::kMaxBounces, "bounces",
            "must be in [0, " + std::to_string(scene::kMaxBounces) + "]");
  out.render.width = s.width.value_or(out.render.width);
  out.render.height = s.height.value_or(out.render.height);
  out.render.samplesPerPixel = s.samplesPerPixel.value_or(out.render.samplesPerPixel);
  if (s.method)
    out.render.method =
        *s.method == Method::Exact ? scene::IntersectionMethod::Exact : scene::IntersectionMethod::Tessellated;
  if (s.tessellationRate) out.render.tessellationRate = s.tessellationRate;
  out.render.bounces = s.bounces.value_or(out.render.bounces);
  require(scene::pathsCountEnvironmentOnce(out.render.bounces, out.environment), "bounces",
          scene::kBouncesNeedOcclusionRule);
  return out;
}

}  // namespace

const Aov& Image::aov(const std::string& name) const {
  const auto found = aovs.find(name);
  if (found == aovs.end()) throw Error(ErrorKind::BadInput, "image: no AOV named '" + name + "'");
  return found->second;
}

struct Renderer::State {
  explicit State(const std::string& adapter) : engine(adapter) {}
  // The engine's renderer holds one GPU context and its buffers: one render at a time.
  std::mutex rendering;
  facet::Renderer engine;
};

Renderer::Renderer(const std::string& adapter) : state_(std::make_unique<State>(adapter)) {}
Renderer::~Renderer() = default;

RenderResult Renderer::render(const Scene& input, const RenderSettings& settings) {
  return api::translateErrors([&] {
    const std::scoped_lock oneAtATime(state_->rendering);
    const scene::Scene s = withSettings(input, settings);
    scene::checkImagesFitInMemory(s, 1, "render settings: width x height");
    const RenderReport report =
        state_->engine.render(s, settings.backend == Backend::Cpu ? facet::Backend::Cpu : facet::Backend::Gpu);
    RenderResult result{publicImage(report.image), report.device, report.totalMilliseconds(), {}};
    for (const cpu::BounceRays& rays : report.raysPerBounce)
      result.raysPerBounce.push_back({rays.rays, rays.hits, rays.shadowRays});
    return result;
  });
}

ParityReport Renderer::parity(const Scene& input, const RenderSettings& settings) {
  return api::translateErrors([&] {
    const std::scoped_lock oneAtATime(state_->rendering);
    const scene::Scene s = withSettings(input, settings);
    scene::checkImagesFitInMemory(s, 2, "render settings: width x height");
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

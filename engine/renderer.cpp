#include "engine/renderer.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <utility>

#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_fault.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "engine/gpu_backend/pipeline_cache_file.h"
#include "scenes/light_transport.h"
#include "scenes/scene_geometry.h"

namespace facet {
namespace {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

gpu::InstanceDescriptor gpuInstanceFromEnvironment() {
  const char* validation = std::getenv("FACET_VALIDATION");
  if (!validation || !*validation || std::strcmp(validation, "0") == 0) return {gpu::Validation::Off};
  return {std::strcmp(validation, "required") == 0 ? gpu::Validation::Required : gpu::Validation::IfInstalled};
}

gpu::AdapterOptions gpuAdapterFromEnvironment(const std::string& adapter) {
  if (!adapter.empty()) return {adapter};
  const char* named = std::getenv("FACET_ADAPTER");
  return {named ? named : ""};
}

const char* toString(Backend backend) {
  switch (backend) {
    case Backend::Cpu:
      return "cpu";
    case Backend::Gpu:
      return "gpu";
  }
  return "?";
}

double RenderReport::totalMilliseconds() const {
  double total = 0;
  for (const StageTime& s : stages) total += s.milliseconds;
  return total;
}

struct Renderer::GpuContext {
  gpu::Instance instance;
  gpu::Device device;
  std::unique_ptr<gpu_backend::GpuRenderer> renderer;
  // Start-up, told by the first GPU render: the Device stage and the cache's warning.
  std::optional<double> deviceMilliseconds;
  std::string pipelineCacheWarning;
};

Renderer::Renderer(std::string adapter) : adapter_(std::move(adapter)) {}

Renderer::~Renderer() = default;

Renderer::GpuContext& Renderer::gpuContext() {
  if (!gpu_) {
    Stopwatch clock;
    auto context = std::make_unique<GpuContext>();
    context->instance = gpu::Instance::create(gpuInstanceFromEnvironment());
    const gpu::Adapter adapter = context->instance.requestAdapter(gpuAdapterFromEnvironment(adapter_));
    gpu_backend::StoredPipelineCache stored = gpu_backend::loadPipelineCache(adapter.info());
    context->device = adapter.requestDevice({"facet render", std::move(stored.data)});
    context->renderer = std::make_unique<gpu_backend::GpuRenderer>(context->device);
    context->deviceMilliseconds = clock.lap();
    context->pipelineCacheWarning = std::move(stored.warning);
    gpu_ = std::move(context);
  }
  return *gpu_;
}

RenderReport render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress,
                    const std::string& adapter) {
  return Renderer(adapter).render(scene, backend, progress);
}

RenderReport Renderer::render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress,
                              const RenderOptions& options) {
  RenderReport report;
  report.window = options.crop.value_or(PixelRect::whole(scene.render.width, scene.render.height));
  if (report.window.empty() || !report.window.inside(scene.render.width, scene.render.height))
    throw std::invalid_argument("crop " + report.window.text() + ": must be a non-empty rectangle inside the " +
                                std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height) +
                                " image");
  Stopwatch clock;
  const std::shared_ptr<const scene::SceneGeometry> built =
      options.geometry ? options.geometry : std::make_shared<const scene::SceneGeometry>(scene::buildGeometry(scene));
  const scene::SceneGeometry& geometry = *built;
  // Decided once, here, so that both backends render the same scene.
  const scene::LightTransport transport = scene::chooseLightTransport(scene, geometry);
  std::optional<scene::Scene> chosen;
  if (scene::changesScene(transport, scene)) scene::applyLightTransport(transport, chosen.emplace(scene));
  const scene::Scene& rendered = chosen ? *chosen : scene;
  report.lightTransport = transport;
  report.samplesPerPixel = scene.render.samplesPerPixel;
  report.warnings.insert(report.warnings.end(), transport.warnings.begin(), transport.warnings.end());
  report.stages.push_back({Stage::RefineBvh, clock.lap()});
  report.patches = geometry.patchCount();
  report.geometrySummary = scene::describe(scene, geometry);
  if (!transport.note.empty()) report.geometrySummary += "\n" + transport.note;
  switch (backend) {
    case Backend::Cpu: {
      cpu::ReferenceStatistics statistics;
      report.image = cpu::renderReference(rendered, geometry, &statistics, progress, options.crop, options.threads);
      const double milliseconds = clock.lap();
      if (rendered.environment) report.stages.push_back({Stage::Environment, statistics.environmentMilliseconds});
      report.stages.push_back({Stage::TraceShade, milliseconds - statistics.environmentMilliseconds});
      report.device =
          "CPU reference, double precision, " + std::to_string(cpu::resolveThreadCount(options.threads)) + " threads";
      report.primaryRays = statistics.primaryRays;
      report.shadowRays = statistics.shadowRays;
      report.raysPerBounce = std::move(statistics.raysPerBounce);
      break;
    }
    case Backend::Gpu: {
      GpuContext& context = gpuContext();
      if (context.deviceMilliseconds) report.stages.push_back({Stage::Device, *context.deviceMilliseconds});
      context.deviceMilliseconds.reset();
      if (!context.pipelineCacheWarning.empty())
        report.warnings.push_back(std::exchange(context.pipelineCacheWarning, {}));
      gpu_backend::GpuRenderResult result = context.renderer->render(rendered, geometry, progress, options.crop);
      report.image = std::move(result.image);
      report.stages.insert(report.stages.end(), result.stageMilliseconds.begin(), result.stageMilliseconds.end());
      report.device = context.device.adapterInfo().name + " (GPU, float)";
      if (const std::optional<GpuFault> fault = gpuFaultFromEnvironment()) {
        injectFault(*fault, report.image);
        report.device += std::string(" with FACET_FAULT=") + toString(*fault);
      }
      report.primaryRays = result.primaryRays;
      report.shadowRays = result.shadowRays;
      report.newtonFallbacks = result.newtonFallbacks;
      report.cells = result.cells;
      report.gpuBytes = result.gpuBytes;
      for (const gpu_backend::GpuBounceRays& rays : result.raysPerBounce)
        report.raysPerBounce.push_back({rays.rays, rays.hits, rays.shadowRays});
      break;
    }
  }
  return report;
}

}  // namespace facet

#include "engine/renderer.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <thread>

#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
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

// One device and renderer per adapter for the whole process: lavapipe
// compiles a pipeline at its first dispatch, so keeping them pays that once.
struct GpuContext {
  gpu::Instance instance;
  gpu::Device device;
  std::unique_ptr<gpu_backend::GpuRenderer> renderer;
};

GpuContext& gpuContext(const std::string& adapter) {
  static std::map<std::string, std::unique_ptr<GpuContext>> contexts;
  std::unique_ptr<GpuContext>& context = contexts[adapter];
  if (!context) {
    context = std::make_unique<GpuContext>();
    context->instance = gpu::Instance::create(gpuInstanceFromEnvironment());
    context->device =
        context->instance.requestAdapter(gpuAdapterFromEnvironment(adapter)).requestDevice({"facet render"});
    context->renderer = std::make_unique<gpu_backend::GpuRenderer>(context->device);
  }
  return *context;
}

}  // namespace

gpu::InstanceDescriptor gpuInstanceFromEnvironment() {
  const char* validation = std::getenv("FACET_VALIDATION");
  const bool wanted = validation && *validation && std::strcmp(validation, "0") != 0;
  return {wanted ? gpu::Validation::IfInstalled : gpu::Validation::Off};
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

RenderReport render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress,
                    const std::string& adapter) {
  RenderReport report;
  Stopwatch clock;
  scene::SceneGeometry geometry = scene::buildGeometry(scene);
  report.stages.push_back({"refine + BVH", clock.lap()});
  report.patches = geometry.patchCount();
  report.geometrySummary = scene::describe(scene, geometry);
  switch (backend) {
    case Backend::Cpu: {
      cpu::ReferenceStatistics statistics;
      report.image = cpu::renderReference(scene, geometry, &statistics, progress);
      const double milliseconds = clock.lap();
      if (scene.environment) report.stages.push_back({"environment", statistics.environmentMilliseconds});
      report.stages.push_back({"trace + shade", milliseconds - statistics.environmentMilliseconds});
      report.device = "CPU reference, double precision, " +
                      std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " threads";
      report.primaryRays = statistics.primaryRays;
      report.shadowRays = statistics.shadowRays;
      break;
    }
    case Backend::Gpu: {
      GpuContext& context = gpuContext(adapter);
      gpu_backend::GpuRenderResult result = context.renderer->render(scene, geometry, progress);
      report.image = std::move(result.image);
      for (const auto& [name, milliseconds] : result.stageMilliseconds) report.stages.push_back({name, milliseconds});
      report.device = context.device.adapterInfo().name + " (GPU, float)";
      report.primaryRays = result.primaryRays;
      report.shadowRays = result.shadowRays;
      report.newtonFallbacks = result.newtonFallbacks;
      report.cells = result.cells;
      report.gpuBytes = result.gpuBytes;
      break;
    }
  }
  return report;
}

}  // namespace facet

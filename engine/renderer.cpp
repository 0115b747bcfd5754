#include "engine/renderer.h"

#include <chrono>
#include <thread>

#include "engine/cpu/reference_renderer.h"
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

const char* toString(Backend backend) {
  switch (backend) {
    case Backend::Cpu:
      return "cpu";
  }
  return "?";
}

double RenderReport::totalMilliseconds() const {
  double total = 0;
  for (const StageTime& s : stages) total += s.milliseconds;
  return total;
}

RenderReport render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress) {
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
      report.stages.push_back({"trace + shade", clock.lap()});
      report.device = "CPU reference, double precision, " +
                      std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " threads";
      report.primaryRays = statistics.primaryRays;
      report.shadowRays = statistics.shadowRays;
      break;
    }
  }
  return report;
}

}  // namespace facet

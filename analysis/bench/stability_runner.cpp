#include "analysis/bench/stability_runner.h"

#include <chrono>
#include <map>
#include <optional>
#include <sstream>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"

namespace facet::analysis::bench::stability {

using scene::IntersectionMethod;

std::string methodsText(const Tolerances& t) {
  std::ostringstream text;
  text << "Tolerances: exact methods depth " << cell(t.exact.depthRelative) << " relative, normal "
       << cell(t.exact.normalRadians) << " rad, beauty " << cell(t.exact.beautyRelative)
       << " relative; tessellated (k = " << kTessellationRate << ", chord error included) depth "
       << cell(t.tessellated.depthRelative) << ", normal " << cell(t.tessellated.normalRadians) << " rad, beauty "
       << cell(t.tessellated.beautyRelative)
       << ". A hole is a pixel the reference covers with all 8 neighbours that the method misses; a Newton miss "
          "a pixel a CPU tessellation at k = "
       << kCoverageRate << " covers with all 8 neighbours that an exact method misses.";
  return text.str();
}

scene::Scene Runner::sceneOf(scene::ControlCage cage) const {
  scene::Scene scene = scene::sceneFromCage(std::move(cage));
  scene.render.width = scene.render.height = size_;
  return scene;
}

Image Runner::render(scene::Scene scene, const Method& method, double* milliseconds) {
  scene.render.method = method.intersection;
  if (method.intersection == IntersectionMethod::Tessellated) scene.render.tessellationRate = kTessellationRate;
  const auto start = std::chrono::steady_clock::now();
  RenderReport report = renderer_.render(scene, method.backend);
  if (milliseconds)
    *milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++renders_;
  return std::move(report.image);
}

void Runner::run(Sweep& sweep, std::size_t column, const scene::Scene& scene, const std::vector<Method>& methods,
                 const std::function<void(scene::Scene&, const std::string&)>& light, bool newton,
                 const std::function<Image()>& converged) {
  struct Timed {
    Image image;
    double milliseconds = 0;
  };
  std::map<std::string, Timed> references;
  auto lit = [&](const std::string& lighting) {
    scene::Scene copy = scene;
    if (light) light(copy, lighting);
    return copy;
  };
  std::optional<Image> coverage;
  if (newton) {
    // Coverage only: no environment to prepare or sample.
    scene::Scene dense = scene;
    dense.environment.reset();
    dense.render.method = IntersectionMethod::Tessellated;
    dense.render.tessellationRate = kCoverageRate;
    coverage = renderer_.render(dense, Backend::Cpu).image;
    ++renders_;
  }
  std::optional<Image> convergedImage;
  if (converged) convergedImage = converged();
  for (const Method& method : methods) {
    if (!references.count(method.lighting)) {
      Timed& reference = references[method.lighting];
      reference.image = render(lit(method.lighting), {"", Backend::Cpu, IntersectionMethod::Exact, method.lighting},
                               &reference.milliseconds);
    }
    const Timed& reference = references[method.lighting];
    const bool isReference = method.backend == Backend::Cpu && method.intersection == IntersectionMethod::Exact;
    double milliseconds = reference.milliseconds;
    Image image;
    try {
      image = isReference ? reference.image : render(lit(method.lighting), method, &milliseconds);
    } catch (const scene::InputError&) {  // beyond the backend's range: every pixel fails
      Cell refused;
      refused.row = method.label;
      refused.column = column;
      refused.failureShare = 1;
      sweep.cells.push_back(refused);
      continue;
    }
    const Image* dense = coverage && method.intersection == IntersectionMethod::Exact ? &*coverage : nullptr;
    Cell c = stability::measure(image, reference.image, dense, tolerances_.of(method.intersection));
    c.row = method.label;
    c.column = column;
    c.milliseconds = milliseconds;
    if (convergedImage) c.methodError = compareToReference(image, *convergedImage).relativeRmse;
    sweep.cells.push_back(c);
  }
}

}  // namespace facet::analysis::bench::stability

#include "analysis/bench/pareto_scenarios.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

#include "scenes/light_transport.h"
#include "scenes/scene_file.h"

namespace facet::analysis::bench::pareto {
namespace {

std::vector<Setting> geometrySettings(const Sizes& sizes) {
  std::vector<Setting> settings;
  for (double epsilon : sizes.tolerances) settings.push_back({"exact", "epsilon", epsilon});
  for (int k : sizes.tessellationRates) settings.push_back({"tessellated", "k", double(k)});
  return settings;
}

}  // namespace

Sizes sizesFor(bool quick) {
  if (quick) return {48, 24, 32, 32, 16, {"pole24"}, {1e-4}, {2, 4}, {1, 4}, 16, {1, 4, 16}};
  return {192,
          96,
          96,
          48,
          24,
          {"pole24", "valence_3_to_10", "creased_box"},
          {1e-3, 1e-4, 1e-5, 1e-6},
          {1, 2, 4, 8, 16},
          {1, 4, 16, 64, 256},
          1024,
          {1, 2, 4, 8, 16, 32, 64}};
}

double chartedError(const ImageError& e, ErrorAxis axis) {
  return axis == ErrorAxis::Beauty ? e.relativeRmse : e.depthRelativeMean;
}

std::string axisName(ErrorAxis axis) {
  return axis == ErrorAxis::Beauty ? "beauty relative RMSE" : "mean relative depth error";
}

double goodEnough(ErrorAxis axis) { return axis == ErrorAxis::Beauty ? 0.01 : 1e-4; }

double gpuToleranceFloor(const scene::Scene& scene) {
  const scene::Aabb bounds = scene::cageBounds(scene);
  double largest = 0;
  for (const glm::dvec3& p : {bounds.lo, bounds.hi, scene.camera.eye})
    for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(p[i]));
  return std::ldexp(largest, -20) / glm::length(bounds.hi - bounds.lo);
}

std::vector<Scenario> scenarios(const BenchOptions& options, const Sizes& sizes) {
  std::vector<Scenario> list;
  const scene::Scene preview = scene::loadStatedScene(options.root / "scenes/examples/preview.json");

  Scenario defaultPreview{"preview", "", preview, ErrorAxis::Beauty, geometrySettings(sizes)};
  defaultPreview.scene.render.width = sizes.previewWidth;
  defaultPreview.scene.render.height = sizes.previewHeight;
  defaultPreview.description = "the default preview (scenes/examples/preview.json: key light, courtyard prefiltered)";
  list.push_back(defaultPreview);

  for (const std::string& cage : sizes.cages) {
    Scenario torture{cage, "", scene::loadStatedScene(options.root / ("scenes/cages/" + cage + ".obj")), ErrorAxis::Depth,
                     geometrySettings(sizes)};
    torture.scene.render.width = torture.scene.render.height = sizes.cageSize;
    torture.description = "torture cage scenes/cages/" + cage + ".obj, default framing and key light";
    torture.embreePeer = true;
    list.push_back(torture);
  }

  // The environment alone, sampled with shadow rays against the split sum:
  // the sun makes the sampled method's variance and the split sum's missing
  // occlusion both show. The geometry is tessellated at a fixed k so that
  // the points differ in lighting alone and N = 256 stays affordable.
  Scenario ibl{"ibl_sunrise", "", preview, ErrorAxis::Beauty, {}};
  ibl.scene.render.width = sizes.iblWidth;
  ibl.scene.render.height = sizes.iblHeight;
  ibl.scene.lights.clear();
  ibl.scene.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(options.root / "scenes/environments/sunrise.exr"));
  ibl.scene.environment->occlusion = true;
  ibl.scene.render.method = scene::IntersectionMethod::Tessellated;
  ibl.scene.render.tessellationRate = 8;
  for (int n : sizes.iblSamples) ibl.settings.push_back({"sampled", "N", double(n)});
  ibl.settings.push_back({"prefiltered", "", 0});
  ibl.referenceSamples = sizes.referenceSamples;
  ibl.description =
      "the preview's geometry lit by scenes/environments/sunrise.exr alone (bright sun), occlusion on, "
      "tessellated k=8";
  list.push_back(ibl);
  return list;
}

}  // namespace facet::analysis::bench::pareto

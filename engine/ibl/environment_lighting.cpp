#include "engine/ibl/environment_lighting.h"

#include <glm/trigonometric.hpp>

#include "rules/rules.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

namespace facet::ibl {

namespace m = rules::f64;

bool filteredUsesEnvironmentSamples(const scene::EnvironmentMap& map) {
  double largest = 0, weighted = 0;
  for (int y = 0; y < map.height; ++y) {
    const double solidAngle = m::environment_texel_solid_angle(y, map.width, map.height);
    for (int x = 0; x < map.width; ++x) {
      const double luminance = m::luminance(glm::dvec3(map.texel(x, y)));
      largest = std::max(largest, luminance);
      weighted += luminance * solidAngle;
    }
  }
  return m::filtered_uses_environment_samples(largest, weighted / (4 * m::PI));
}

namespace {

// The distribution of the last map asked for, kept with the map itself (so
// that its address cannot be another map's): the rounds, frames and cells
// of one scene build it once.
EnvironmentDistribution distributionOf(const std::shared_ptr<const scene::EnvironmentMap>& map) {
  static std::mutex mutex;
  static std::shared_ptr<const scene::EnvironmentMap> lastMap;
  static std::shared_ptr<const EnvironmentDistribution> last;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (lastMap == map) return *last;
  }
  auto built = std::make_shared<const EnvironmentDistribution>(buildDistribution(*map));
  const std::lock_guard<std::mutex> lock(mutex);
  lastMap = map;
  last = built;
  return *built;
}

}  // namespace

EnvironmentLighting prepareEnvironmentLighting(const scene::Scene& scene, const PrefilterBuilder& prefilter) {
  EnvironmentLighting lighting;
  const scene::Environment& environment = *scene.environment;
  lighting.environment = &environment;
  lighting.cosRotation = std::cos(glm::radians(environment.rotationDegrees));
  lighting.sinRotation = std::sin(glm::radians(environment.rotationDegrees));
  switch (environment.method) {
    case scene::IblMethod::Sampled:
      lighting.distribution = distributionOf(environment.map);
      break;
    case scene::IblMethod::Prefiltered: {
      ModelPairs pairs;
      for (const materials::Material& material : scene.materials) {
        lighting.dfgTable.push_back(modelPairIndex(pairs, material));
        if (material.clearcoat > 0.0 && lighting.coatDfgTable < 0) {
          materials::Material coat;  // the coat's lobe (rules/shading/clearcoat.h)
          coat.distribution = m::D_GGX;
          coat.geometry = m::G_SMITH_GGX_CORRELATED;
          lighting.coatDfgTable = modelPairIndex(pairs, coat);
        }
      }
      lighting.prefiltered = prefilter(*environment.map, pairs);
      break;
    }
    case scene::IblMethod::Filtered:
      lighting.mipChain = mipChain(*environment.map);
      lighting.environmentSamples = filteredUsesEnvironmentSamples(*environment.map);
      if (lighting.environmentSamples) {
        lighting.distribution = distributionOf(environment.map);
        scene::EnvironmentMap density;
        density.width = environment.map->width;
        density.height = environment.map->height;
        for (double pdf : lighting.distribution.texelPdf) density.rgb.insert(density.rgb.end(), 3, float(pdf));
        lighting.pdfChain = mipChain(density);
      }
      break;
  }
  return lighting;
}

}  // namespace facet::ibl

#include "engine/ibl/environment_lighting.h"

#include <glm/trigonometric.hpp>

#include "engine/ibl/last_result.h"
#include "rules/rules.h"

#include <algorithm>
#include <cmath>
#include <memory>

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

// The distribution of the last map asked for, keyed by the map itself, whose
// pointer held here keeps its address from becoming another map's.
EnvironmentDistribution distributionOf(const std::shared_ptr<const scene::EnvironmentMap>& map) {
  static LastResult<std::shared_ptr<const scene::EnvironmentMap>, EnvironmentDistribution> last;
  return last.get(map, [&] { return buildDistribution(*map); });
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

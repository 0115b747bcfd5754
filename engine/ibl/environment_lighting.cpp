#include "engine/ibl/environment_lighting.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace facet::ibl {

EnvironmentLighting prepareEnvironmentLighting(const scene::Scene& scene, const PrefilterBuilder& prefilter) {
  EnvironmentLighting lighting;
  const scene::Environment& environment = *scene.environment;
  lighting.environment = &environment;
  lighting.cosRotation = std::cos(glm::radians(environment.rotationDegrees));
  lighting.sinRotation = std::sin(glm::radians(environment.rotationDegrees));
  switch (environment.method) {
    case scene::IblMethod::Sampled:
      lighting.distribution = buildDistribution(*environment.map);
      break;
    case scene::IblMethod::Prefiltered: {
      ModelPairs pairs;
      for (const materials::Material& material : scene.materials) {
        const std::pair<int, int> pair{material.distribution, material.geometry};
        auto found = std::find(pairs.begin(), pairs.end(), pair);
        lighting.dfgTable.push_back(int(found - pairs.begin()));
        if (found == pairs.end()) pairs.push_back(pair);
      }
      lighting.prefiltered = prefilter(*environment.map, pairs);
      break;
    }
  }
  return lighting;
}

}  // namespace facet::ibl

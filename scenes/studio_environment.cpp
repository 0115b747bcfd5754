#include "scenes/studio_environment.h"

#include <memory>

#include "facet_studio_map/data.h"

namespace facet::scene {

EnvironmentMap studioEnvironmentMap() {
  EnvironmentMap map = decodeExrEnvironmentMap(embedded::studio, kStudioEnvironmentName);
  // Three texels of about -3e-6, DWAB's rounding, are set to 0 as in any
  // map; the program's own map is no input of the user's to warn about.
  map.clampedTexels = 0;
  return map;
}

Environment studioEnvironment() {
  static const std::shared_ptr<const EnvironmentMap> map =
      std::make_shared<const EnvironmentMap>(studioEnvironmentMap());
  Environment environment;
  environment.map = map;
  environment.rotationDegrees = kStudioRotationDegrees;
  environment.methodStated = false;
  environment.samplesStated = false;
  return environment;
}

bool isStudioEnvironment(const Environment& environment) { return environment.map->source == kStudioEnvironmentName; }

}  // namespace facet::scene

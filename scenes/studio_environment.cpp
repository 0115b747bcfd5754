#include "scenes/studio_environment.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <numbers>

namespace facet::scene {
namespace {

// A soft box: radiance peak x exp((cos(angle to centre) - 1) / width), a
// von Mises-Fisher lobe whose angular radius is about sqrt(2 width).
struct SoftBox {
  glm::dvec3 centre;
  double peak;
  double width;
};

double studioRadiance(const glm::dvec3& d) {
  // World-fixed, placed for the default view from (1, 0.75, 1.5): the key
  // above its left shoulder, the fill low on its right, the rim behind.
  static const SoftBox boxes[] = {
      {glm::normalize(glm::dvec3(-0.3, 0.8, 0.6)), 4.0, 0.06},
      {glm::normalize(glm::dvec3(0.9, 0.25, 0.3)), 1.0, 0.08},
      {glm::normalize(glm::dvec3(0.1, 0.45, -0.9)), 2.5, 0.03},
  };
  double radiance = 0.08 + 0.22 * (0.5 + 0.5 * d.y);  // floor 0.08 to ceiling 0.3
  for (const SoftBox& box : boxes) radiance += box.peak * std::exp((glm::dot(d, box.centre) - 1.0) / box.width);
  return radiance;
}

}  // namespace

EnvironmentMap studioEnvironmentMap() {
  EnvironmentMap map;
  map.source = kStudioEnvironmentName;
  map.width = 256;
  map.height = 128;
  map.rgb.reserve(std::size_t(3 * map.width * map.height));
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      // rules/environment/environment_mapping.h's direction of the texel's centre.
      const double phi = 2.0 * std::numbers::pi * ((x + 0.5) / map.width - 0.5);
      const double theta = std::numbers::pi * (y + 0.5) / map.height;
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      const float radiance = float(studioRadiance(d));
      map.rgb.insert(map.rgb.end(), {radiance, radiance, radiance});
    }
  return map;
}

Environment studioEnvironment() {
  static const std::shared_ptr<const EnvironmentMap> map =
      std::make_shared<const EnvironmentMap>(studioEnvironmentMap());
  Environment environment;
  environment.map = map;
  environment.methodStated = false;
  environment.samplesStated = false;
  return environment;
}

bool isStudioEnvironment(const Environment& environment) { return environment.map->source == kStudioEnvironmentName; }

}  // namespace facet::scene

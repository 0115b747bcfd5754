#include "analysis/bench/stability_scenes.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>

#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"

namespace facet::analysis::bench::stability {

scene::ControlCage planeCage() {
  std::ostringstream obj;
  constexpr int n = 8;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) obj << "v " << -6 + 12.0 * i / n << " 0 " << -6 + 12.0 * j / n << "\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1;
      obj << "f " << a << " " << a + n + 1 << " " << a + n + 2 << " " << a + 1 << "\n";
    }
  return scene::parseObjCage(obj.str(), "stability plane");
}

scene::ControlCage poleCage(int n) {
  std::ostringstream obj;
  const int m = 2 * n;
  auto ring = [&](double y, double radius) {
    for (int k = 0; k < m; ++k) {
      const double phi = 2 * std::numbers::pi * k / m;
      obj << "v " << radius * std::cos(phi) << " " << y << " " << radius * std::sin(phi) << "\n";
    }
  };
  ring(0.5, std::sqrt(0.75));
  ring(-0.5, std::sqrt(0.75));
  obj << "v 0 1 0\nv 0 -1 0\n";
  const int top = 2 * m + 1, bottom = 2 * m + 2;
  auto upper = [&](int k) { return k % m + 1; };
  auto lower = [&](int k) { return m + k % m + 1; };
  for (int i = 0; i < n; ++i) {
    obj << "f " << top << " " << upper(2 * i + 2) << " " << upper(2 * i + 1) << " " << upper(2 * i) << "\n";
    obj << "f " << bottom << " " << lower(2 * i) << " " << lower(2 * i + 1) << " " << lower(2 * i + 2) << "\n";
  }
  for (int k = 0; k < m; ++k)
    obj << "f " << upper(k) << " " << upper(k + 1) << " " << lower(k + 1) << " " << lower(k) << "\n";
  return scene::parseObjCage(obj.str(), "stability pole " + std::to_string(n));
}

scene::ControlCage creasedCube(double sharpness) {
  std::ostringstream obj;
  obj << "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
         "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  if (sharpness > 0) obj << "t crease 8/1/0 2 6 6 7 7 3 3 2 " << sharpness << "\n";
  return scene::parseObjCage(obj.str(), "stability creased cube");
}

scene::ControlCage cubeCage() { return creasedCube(0); }

scene::Environment environmentOf(scene::EnvironmentMap map) {
  scene::Environment environment;
  environment.map = std::make_shared<const scene::EnvironmentMap>(std::move(map));
  return environment;
}

scene::EnvironmentMap sunEnvironment(double sun) {
  scene::EnvironmentMap map;
  map.width = 64;
  map.height = 32;
  map.rgb.assign(std::size_t(map.width) * map.height * 3, 1.0f);
  for (int y = 10; y < 12; ++y)
    for (int x = 54; x < 56; ++x)
      for (int c = 0; c < 3; ++c) map.rgb[3 * (std::size_t(y) * map.width + x) + c] = float(sun);
  return map;
}

materials::Material metal(double alpha, const glm::dvec3& f0) {
  materials::Material m = scene::defaultMaterial();
  m.name = "metal";
  m.f0 = f0;
  m.diffuse = glm::dvec3(0.0);
  m.alpha = alpha;
  return m;
}

}  // namespace facet::analysis::bench::stability

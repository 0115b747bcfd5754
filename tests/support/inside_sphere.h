// The closed diffuse sphere of the path tests: the camera and a point light
// of c_light = 1 at the centre of a closed Lambertian sphere of albedo rho.
// Every point receives irradiance pi, so the direct radiance is L0 = rho
// everywhere and each bounce multiplies it by rho (pbrt-v4's sphere test:
// Kd 0.5 gives 0.5 direct, 1.0 converged). Needs FACET_CAGE_DIR (blob_scene.h).
#pragma once

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/image/image.h"
#include "scenes/scene.h"
#include "tests/support/blob_scene.h"

namespace facet::testing {

// A UV sphere of radius 1 about the origin, `rings` x `segments` faces
// (quads, and triangles at the poles), rendered as authored.
inline scene::ControlCage uvSphereCage(int rings, int segments) {
  scene::ControlCage cage;
  cage.source = "uv sphere";
  cage.positions.push_back({0.0, 1.0, 0.0});
  for (int ring = 1; ring < rings; ++ring) {
    const double theta = glm::pi<double>() * ring / rings;
    for (int segment = 0; segment < segments; ++segment) {
      const double phi = 2.0 * glm::pi<double>() * segment / segments;
      cage.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  }
  cage.positions.push_back({0.0, -1.0, 0.0});
  const int south = int(cage.positions.size()) - 1;
  auto at = [&](int ring, int segment) { return 1 + (ring - 1) * segments + segment % segments; };
  auto face = [&](std::vector<int> vertices) {
    cage.faceVertexCounts.push_back(int(vertices.size()));
    cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), vertices.begin(), vertices.end());
  };
  for (int s = 0; s < segments; ++s) {
    face({0, at(1, s + 1), at(1, s)});
    for (int ring = 1; ring + 1 < rings; ++ring)
      face({at(ring, s), at(ring, s + 1), at(ring + 1, s + 1), at(ring + 1, s)});
    face({south, at(rings - 1, s), at(rings - 1, s + 1)});
  }
  return cage;
}

// size x size pixels at `samplesPerPixel`, tessellated.
inline scene::Scene insideDiffuseSphere(double albedo, int bounces, int size, int samplesPerPixel) {
  scene::Scene s;
  s.materials.push_back(lambertian(albedo));
  scene::Object sphere;
  sphere.name = "sphere";
  sphere.cage = uvSphereCage(32, 64);
  sphere.subdivision = scene::Subdivision::None;
  s.objects.push_back(std::move(sphere));
  scene::Light light;
  light.type = scene::LightType::Point;
  light.position = glm::dvec3(0.0);
  s.lights.push_back(light);
  s.camera.eye = glm::dvec3(0.0);
  s.camera.target = {0.0, 0.2, -1.0};
  s.camera.verticalFovDegrees = 90;
  s.render.width = s.render.height = size;
  s.render.samplesPerPixel = samplesPerPixel;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.render.bounces = bounces;
  return s;
}

struct PixelMean {
  double mean = 0;
  double standardError = 0;  // of the mean, from the pixels' spread
};

// The mean over pixels of the beauty's channel mean.
inline PixelMean meanRadiance(const Image& image) {
  double sum = 0, sumSquares = 0;
  for (const auto& pixel : image.beauty) {
    const double value = (double(pixel.r) + double(pixel.g) + double(pixel.b)) / 3.0;
    sum += value;
    sumSquares += value * value;
  }
  const double n = double(image.beauty.size());
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sumSquares / n - mean * mean) / (n - 1))};
}

// 1 + ratio + ... + ratio^(terms - 1).
inline double geometricSum(double ratio, int terms) {
  double sum = 0, power = 1;
  for (int k = 0; k < terms; ++k, power *= ratio) sum += power;
  return sum;
}

}  // namespace facet::testing

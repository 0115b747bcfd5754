// Transmissive test scenes (docs/rendering.md, "Transmission and
// absorption") that the CPU reference's and the GPU's tests share: a clear
// glass, and an object of it under a uniform white environment (the
// furnace), and glass and ruby balls over a diffuse ground under a map.
#pragma once

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "engine/image/image.h"
#include "materials/material.h"
#include "scenes/environment_map.h"
#include "scenes/scene.h"
#include "tests/support/inside_sphere.h"

namespace facet::testing {

inline materials::Material buildTestMaterial(const materials::MaterialSpec& spec) {
  return materials::buildMaterial(spec, [](std::string_view field) { return std::string(field); });
}

// Mean RGB over the pixels every camera sample of which hit.
inline glm::dvec3 coveredMean(const Image& image) {
  glm::dvec3 sum(0.0);
  int count = 0;
  for (const glm::vec4& pixel : image.beauty)
    if (pixel.a == 1.0f) sum += glm::dvec3(pixel), ++count;
  EXPECT_GT(count, 0);
  return sum / double(std::max(count, 1));
}

// Smooth, clear, transmitting everything its Fresnel lets through.
inline materials::MaterialSpec glassSpec(double ior) {
  materials::MaterialSpec spec;
  spec.name = "glass";
  spec.alpha = 0.0;
  spec.ior = glm::dvec3(ior);
  spec.transmission = 1.0;
  return spec;
}

inline scene::Object testObject(std::string name, scene::ControlCage cage, int material) {
  scene::Object object;
  object.name = std::move(name);
  object.cage = std::move(cage);
  object.material = material;
  object.subdivision = scene::Subdivision::None;
  return object;
}

// `cage` as authored, seen from +z, under a uniform white environment
// sampled 4 times a camera sample, 16 samples a pixel.
inline scene::Scene underWhite(const materials::Material& material, scene::ControlCage cage, int bounces, int size,
                               double fovDegrees) {
  scene::Scene s;
  s.materials.push_back(material);
  s.objects.push_back(testObject("glass", std::move(cage), 0));
  s.camera.eye = {0.0, 0.0, 4.0};
  s.camera.verticalFovDegrees = fovDegrees;
  s.render.width = s.render.height = size;
  s.render.samplesPerPixel = 16;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.render.bounces = bounces;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->samples = 4;
  return s;
}

// A box |x|, |y| <= 3, |z| <= depth / 2, its faces wound outward.
inline scene::ControlCage slab(double depth) {
  scene::ControlCage cage;
  cage.source = "slab";
  for (int i = 0; i < 8; ++i)
    cage.positions.push_back({i & 1 ? 3.0 : -3.0, i & 2 ? 3.0 : -3.0, i & 4 ? depth / 2 : -depth / 2});
  cage.faceVertexCounts = {4, 4, 4, 4, 4, 4};
  cage.faceVertexIndices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4, 2, 6, 7, 3};
  return cage;
}

// A slab's pixel seen face on under a uniform white environment: 1 less
// what the glass absorbs, its two interfaces of reflectance `f` reflecting
// back and forth (Airy's sum), `tau` the transmittance of one crossing.
inline double slabUnderWhite(double f, double tau) {
  return f + (1 - f) * (1 - f) * (f * tau * tau + tau) / (1 - f * f * tau * tau);
}

// A smooth glass ball and a rough ruby one (absorbing all but red) on a
// diffuse ground, under `map` sampled with its shadow rays, `width` x
// `height` pixels of 4 samples.
inline scene::Scene glassAndRubyOnGround(std::shared_ptr<const scene::EnvironmentMap> map, int bounces, int width,
                                         int height) {
  scene::Scene s;
  s.materials.push_back(buildTestMaterial(glassSpec(1.5)));
  materials::MaterialSpec ruby;
  ruby.name = "ruby";
  ruby.preset = "glass-high-ruby";
  ruby.roughness = 0.3;
  s.materials.push_back(buildTestMaterial(ruby));
  materials::MaterialSpec ground;
  ground.name = "ground";
  ground.alpha = 0.5;
  ground.f0 = glm::dvec3(0.04);
  ground.diffuse = glm::dvec3(0.6, 0.55, 0.5);
  s.materials.push_back(buildTestMaterial(ground));
  scene::ControlCage left = uvSphereCage(8, 16), right = uvSphereCage(8, 16);
  for (glm::dvec3& p : left.positions) p += glm::dvec3(-1.1, 0.0, 0.0);
  for (glm::dvec3& p : right.positions) p += glm::dvec3(1.1, 0.0, 0.0);
  scene::ControlCage floor;
  floor.source = "ground";
  floor.positions = {{-6.0, -1.0, -6.0}, {-6.0, -1.0, 6.0}, {6.0, -1.0, 6.0}, {6.0, -1.0, -6.0}};
  floor.faceVertexCounts = {4};
  floor.faceVertexIndices = {0, 1, 2, 3};
  s.objects.push_back(testObject("glass", std::move(left), 0));
  s.objects.push_back(testObject("ruby", std::move(right), 1));
  s.objects.push_back(testObject("ground", std::move(floor), 2));
  s.camera.eye = {0.0, 1.2, 5.0};
  s.camera.target = {0.0, -0.2, 0.0};
  s.camera.verticalFovDegrees = 40.0;
  s.render.width = width;
  s.render.height = height;
  s.render.samplesPerPixel = 4;
  s.render.bounces = bounces;
  s.environment.emplace();
  s.environment->map = std::move(map);
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->occlusion = true;
  s.environment->samples = 2;
  return s;
}

}  // namespace facet::testing

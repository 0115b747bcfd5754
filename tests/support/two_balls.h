// Two subdivided balls side by side under the sun and, optionally, the
// courtyard: the scene the material parity tests of the GPU backend share
// (anisotropy, clear coat, sheen), and the check that a material the kernel is
// specialized for leaves its neighbour's pixels bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

#include "scenes/environment_map.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/path_parity.h"

namespace facet::testing {

// Rough gold (roughness 0.4) at x = -1.1, the neighbour whose pixels the
// tests hold bit for bit, and `right` at x = 1.1; 48 x 24 pixels at 4 spp,
// with `bounces`; lit by the sun and, with a method, the courtyard (2 pairs,
// occluded when sampled).
inline scene::Scene twoBalls(materials::Material right, std::optional<scene::IblMethod> method, int bounces) {
  materials::MaterialSpec gold;
  gold.preset = "gold";
  gold.roughness = 0.4;
  scene::Scene s;
  s.materials.push_back(buildTestMaterial(gold));
  s.materials.push_back(std::move(right));
  scene::ControlCage leftCage = uvSphereCage(8, 16), rightCage = uvSphereCage(8, 16);
  for (glm::dvec3& p : leftCage.positions) p += glm::dvec3(-1.1, 0.0, 0.0);
  for (glm::dvec3& p : rightCage.positions) p += glm::dvec3(1.1, 0.0, 0.0);
  s.objects.push_back(testObject("left", std::move(leftCage), 0));
  s.objects.push_back(testObject("right", std::move(rightCage), 1));
  for (scene::Object& object : s.objects) object.subdivision = scene::Subdivision::CatmullClark;
  scene::Light sun;
  sun.direction = glm::normalize(glm::dvec3(-0.4, -0.6, -1.0));
  sun.color = glm::dvec3(2.0);
  s.lights.push_back(sun);
  s.camera.eye = {0.0, 0.5, 5.0};
  s.camera.verticalFovDegrees = 36.0;
  s.render.width = 48;
  s.render.height = 24;
  s.render.samplesPerPixel = 4;
  s.render.bounces = bounces;
  if (!method) return s;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / "courtyard_256x128.hdr"));
  s.environment->method = *method;
  s.environment->occlusion = method == scene::IblMethod::Sampled;
  s.environment->samples = 2;
  return s;
}

// The left half of two twoBalls renders, which sees only the left ball,
// is the same bits on both backends; the left ball covers part of it.
inline void expectLeftHalfBitForBit(const PathRenders& a, const PathRenders& b, int width, int height) {
  int compared = 0, covered = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width / 2 - 2; ++x) {
      const std::size_t i = std::size_t(y * width + x);
      EXPECT_EQ(std::memcmp(&a.gpu.image.beauty[i], &b.gpu.image.beauty[i], sizeof(glm::vec4)), 0) << x << "," << y;
      EXPECT_EQ(std::memcmp(&a.reference.beauty[i], &b.reference.beauty[i], sizeof(glm::vec4)), 0) << x << "," << y;
      covered += a.gpu.image.beauty[i].a > 0 ? 1 : 0;
      ++compared;
    }
  EXPECT_GT(covered, compared / 8);  // the left ball is in the compared half
}

}  // namespace facet::testing

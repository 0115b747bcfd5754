// A triangle mesh rendered as authored on the CPU reference: flat shading,
// every pixel's normals those of the face it shows, by either intersection
// method.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <set>

#include "engine/cpu/reference_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

namespace facet {
namespace {

class PolygonRender : public ::testing::TestWithParam<scene::IntersectionMethod> {};

TEST_P(PolygonRender, EveryPixelHasTheNormalOfItsFace) {
  scene::Scene scene = scene::loadScene(std::string(FACET_TEST_DATA_DIR) + "/faceted_gem.gltf");
  scene.render.width = 48;
  scene.render.height = 36;
  scene.render.method = GetParam();
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  EXPECT_EQ(geometry.objects.at(0).refinement.tessellationRate, 1);  // flat: two triangles per patch are exact
  const Image image = cpu::renderReference(scene, geometry);

  const scene::ControlCage& cage = scene.objects[0].cage;
  std::set<std::uint32_t> faces;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    if (image.beauty[p].a == 0) continue;
    const std::uint32_t face = image.faceId[p];
    ASSERT_LT(face, std::uint32_t(cage.faceCount()));
    faces.insert(face);
    const glm::dvec3 a = cage.positions[std::size_t(cage.faceVertexIndices[3 * face])];
    const glm::dvec3 b = cage.positions[std::size_t(cage.faceVertexIndices[3 * face + 1])];
    const glm::dvec3 c = cage.positions[std::size_t(cage.faceVertexIndices[3 * face + 2])];
    const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));  // outwards, towards the eye
    EXPECT_LT(glm::length(glm::dvec3(image.shadingNormal[p]) - normal), 1e-6) << "pixel " << p;
    EXPECT_LT(glm::length(glm::dvec3(image.geometricNormal[p]) - normal), 1e-6) << "pixel " << p;
    EXPECT_LT(std::abs(glm::dot(glm::dvec3(image.position[p]) - a, normal)), 1e-5) << "pixel " << p;
  }
  EXPECT_GE(faces.size(), 6u);  // the camera sees about half the gem's twelve faces
}

INSTANTIATE_TEST_SUITE_P(BothMethods, PolygonRender,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated));

}  // namespace
}  // namespace facet

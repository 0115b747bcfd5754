// Where objects stand: a transformed cage keeps each corner's attributes
// with its vertex and its normals perpendicular to the surface, and a
// turntable's frame turns the model about the vertical through the camera's
// target, or the environment, and nothing else.
#include "scenes/placement.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace facet::scene {
namespace {

// Two quads sharing an edge, each corner with its own texture coordinate,
// colour, authored normal and tangent.
ControlCage texturedStrip() {
  ControlCage cage;
  cage.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  cage.faceVertexCounts = {4, 4};
  cage.faceVertexIndices = {0, 1, 4, 3, 1, 2, 5, 4};
  for (int corner = 0; corner < 8; ++corner) {
    cage.texcoords.push_back({0.1 * corner, 0.2});
    cage.faceVertexTexcoords.push_back(corner);
    cage.faceVertexNormals.push_back(glm::normalize(glm::dvec3(0.1 * corner, 0, 1)));
    cage.faceVertexTangents.push_back(glm::dvec4(glm::normalize(glm::dvec3(1, 0.1 * corner, 0)), 1.0));
    cage.colors.push_back(glm::dvec3(corner));
    cage.faceVertexColors.push_back(corner);
  }
  return cage;
}

// Each face's corners as (vertex, texture coordinate, colour) triples.
std::set<std::tuple<int, int, int>> cornersOfFace(const ControlCage& cage, int face) {
  std::set<std::tuple<int, int, int>> corners;
  for (int c = 4 * face; c < 4 * face + 4; ++c)
    corners.insert({cage.faceVertexIndices[c], cage.faceVertexTexcoords[c], cage.faceVertexColors[c]});
  return corners;
}

glm::dvec3 faceNormal(const ControlCage& cage, int face) {
  const auto p = [&](int c) { return cage.positions[std::size_t(cage.faceVertexIndices[std::size_t(4 * face + c)])]; };
  return glm::normalize(glm::cross(p(1) - p(0), p(2) - p(0)));
}

TEST(Placement, AMirrorReversesTheWindingAndKeepsEachCornersAttributesWithItsVertex) {
  const ControlCage before = texturedStrip();
  ControlCage mirrored = before;
  transformCage(mirrored, glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1)));
  for (int face = 0; face < 2; ++face) {
    EXPECT_EQ(cornersOfFace(mirrored, face), cornersOfFace(before, face)) << "face " << face;
    EXPECT_NEAR(glm::dot(faceNormal(mirrored, face), glm::dvec3(0, 0, 1)), 1.0, 1e-12)
        << "face " << face << " still faces +z, as the mirrored surface does";
  }
  EXPECT_EQ(mirrored.positions[2], glm::dvec3(-2, 0, 0));
  for (std::size_t c = 0; c < 8; ++c) {
    // Each authored normal travels with its corner and is mirrored in x.
    const int corner = mirrored.faceVertexColors[c];
    const glm::dvec3 authored = before.faceVertexNormals[std::size_t(corner)];
    EXPECT_NEAR(glm::length(mirrored.faceVertexNormals[c] - glm::dvec3(-authored.x, authored.y, authored.z)), 0, 1e-12);
    // So does its tangent, mirrored as the surface is, its sign flipped:
    // n x t turned against the mirrored bitangent.
    const glm::dvec4 tangent = before.faceVertexTangents[std::size_t(corner)];
    EXPECT_NEAR(glm::length(glm::dvec3(mirrored.faceVertexTangents[c]) - glm::dvec3(-tangent.x, tangent.y, tangent.z)),
                0, 1e-12);
    EXPECT_EQ(mirrored.faceVertexTangents[c].w, -1.0);
  }
}

TEST(Placement, AuthoredNormalsStayPerpendicularUnderANonUniformScale) {
  ControlCage cage = texturedStrip();
  const glm::dvec3 tangent(1, 0, -0.3);  // in the plane the first normal is perpendicular to
  cage.faceVertexNormals[0] = glm::normalize(glm::dvec3(0.3, 0, 1));
  ASSERT_NEAR(glm::dot(tangent, cage.faceVertexNormals[0]), 0, 1e-12);
  const glm::dmat4 stretch = glm::scale(glm::dmat4(1.0), glm::dvec3(3, 1, 0.5));
  transformCage(cage, stretch);
  const glm::dvec3 stretchedTangent = glm::dvec3(stretch * glm::dvec4(tangent, 0));
  EXPECT_NEAR(glm::dot(stretchedTangent, cage.faceVertexNormals[0]), 0, 1e-12);
  EXPECT_NEAR(glm::length(cage.faceVertexNormals[0]), 1, 1e-12);
}

Scene sceneAround(glm::dvec3 target) {
  Scene s;
  Object object;
  object.cage = texturedStrip();
  s.objects.push_back(object);
  s.camera.eye = target + glm::dvec3(0, 1, 5);
  s.camera.target = target;
  s.lights.push_back({});
  s.environment.emplace();
  s.environment->rotationDegrees = 10;
  return s;
}

TEST(Placement, ATurntableTurnsTheModelAboutTheVerticalThroughTheTarget) {
  const glm::dvec3 target(1, 0.5, -2);
  const Scene still = sceneAround(target);
  for (int frame = 0; frame < 8; ++frame) {
    const Scene turned = turntableFrame(still, frame, 8, TurntableTurn::Model);
    for (std::size_t v = 0; v < still.objects[0].cage.positions.size(); ++v) {
      const glm::dvec3 a = still.objects[0].cage.positions[v] - target,
                       b = turned.objects[0].cage.positions[v] - target;
      EXPECT_NEAR(b.y, a.y, 1e-12) << "heights are kept";
      EXPECT_NEAR(glm::length(glm::dvec2(b.x, b.z)), glm::length(glm::dvec2(a.x, a.z)), 1e-12);
    }
    EXPECT_EQ(turned.camera.eye, still.camera.eye);
    EXPECT_EQ(turned.lights[0].direction, still.lights[0].direction);
    EXPECT_EQ(turned.environment->rotationDegrees, 10);
  }
  // A quarter turn, right-handed about +y, takes +x to -z.
  const Scene quarter = turntableFrame(still, 2, 8, TurntableTurn::Model);
  const glm::dvec3 moved = quarter.objects[0].cage.positions[2] - target;  // (2, 0, 0) before
  const glm::dvec3 from = still.objects[0].cage.positions[2] - target;
  EXPECT_NEAR(moved.x, from.z, 1e-12);
  EXPECT_NEAR(moved.z, -from.x, 1e-12);
  EXPECT_EQ(turntableFrame(still, 0, 8, TurntableTurn::Model).objects[0].cage.positions,
            still.objects[0].cage.positions);
}

TEST(Placement, ATurntableOfTheEnvironmentTurnsItAloneAndNeedsOne) {
  const Scene still = sceneAround({0, 0, 0});
  const Scene turned = turntableFrame(still, 3, 12, TurntableTurn::Environment);
  EXPECT_DOUBLE_EQ(turned.environment->rotationDegrees, 10 + 90);
  EXPECT_EQ(turned.objects[0].cage.positions, still.objects[0].cage.positions);
  Scene unlit = still;
  unlit.environment.reset();
  try {
    turntableFrame(unlit, 1, 4, TurntableTurn::Environment);
    FAIL() << "an environment turntable without an environment";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--turn environment: the scene has no environment map", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace facet::scene

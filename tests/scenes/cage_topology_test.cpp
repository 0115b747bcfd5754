// What a cage's faces close into (scenes/cage_topology.h): a sphere of faces
// for the light-transport choice, and solids wound outward, of any genus and
// in any number of pieces, for the inside of glass.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "scenes/cage_topology.h"
#include "tests/support/cages.h"

namespace facet::scene {
namespace {

// The cube [-1, 1]^3, its faces wound counter-clockwise seen from outside.
ControlCage outwardBox() {
  ControlCage cage;
  cage.source = "box";
  for (int i = 0; i < 8; ++i) cage.positions.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  cage.faceVertexCounts = {4, 4, 4, 4, 4, 4};
  cage.faceVertexIndices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4, 2, 6, 7, 3};
  return cage;
}

// Every face wound the other way.
ControlCage turnedInside(ControlCage cage) {
  std::size_t first = 0;
  for (int count : cage.faceVertexCounts) {
    std::reverse(cage.faceVertexIndices.begin() + std::ptrdiff_t(first),
                 cage.faceVertexIndices.begin() + std::ptrdiff_t(first + std::size_t(count)));
    first += std::size_t(count);
  }
  return cage;
}

// Both cages' faces in one cage, the second's moved by `dx` along x.
ControlCage together(ControlCage a, const ControlCage& b, double dx) {
  const int offset = a.vertexCount();
  for (glm::dvec3 p : b.positions) a.positions.push_back(p + glm::dvec3(dx, 0.0, 0.0));
  a.faceVertexCounts.insert(a.faceVertexCounts.end(), b.faceVertexCounts.begin(), b.faceVertexCounts.end());
  for (int v : b.faceVertexIndices) a.faceVertexIndices.push_back(v + offset);
  return a;
}

// The box with one face wound against its neighbours.
ControlCage oneFaceFlipped() {
  ControlCage cage = outwardBox();
  std::swap(cage.faceVertexIndices[1], cage.faceVertexIndices[3]);
  return cage;
}

// The box without its last face.
ControlCage oneFaceMissing() {
  ControlCage cage = outwardBox();
  cage.faceVertexCounts.pop_back();
  cage.faceVertexIndices.resize(cage.faceVertexIndices.size() - 4);
  return cage;
}

TEST(CageTopology, OnlyASphereOfFacesCloses) {
  EXPECT_TRUE(closesIntoSphere(outwardBox()));
  EXPECT_FALSE(closesIntoSphere(oneFaceFlipped()));
  EXPECT_FALSE(closesIntoSphere(oneFaceMissing()));
  EXPECT_FALSE(closesIntoSphere(together(outwardBox(), outwardBox(), 3.0)));  // two closed pieces
  EXPECT_FALSE(closesIntoSphere(testing::torusCage(12, 8, 1.0, 0.35)));       // genus 1
}

TEST(CageTopology, SolidsAreClosedAndWoundOutward) {
  EXPECT_TRUE(enclosesSolid(outwardBox()));
  EXPECT_FALSE(enclosesSolid(turnedInside(outwardBox())));  // closed, but its outside faces in
  EXPECT_FALSE(enclosesSolid(oneFaceFlipped()));
  EXPECT_FALSE(enclosesSolid(oneFaceMissing()));
  ControlCage holed = outwardBox();
  holed.holes = {2};
  EXPECT_FALSE(enclosesSolid(holed));
  // Pieces count one by one: a larger outward box does not make up for an inward one.
  EXPECT_TRUE(enclosesSolid(together(outwardBox(), outwardBox(), 3.0)));
  ControlCage large = outwardBox();
  for (glm::dvec3& p : large.positions) p *= 3.0;
  EXPECT_FALSE(enclosesSolid(together(large, turnedInside(outwardBox()), 10.0)));
  // Any genus: a torus is a solid wound one way or the other.
  const ControlCage torus = testing::torusCage(12, 8, 1.0, 0.35);
  EXPECT_NE(enclosesSolid(torus), enclosesSolid(turnedInside(torus)));
}

}  // namespace
}  // namespace facet::scene

// A UV sphere cage for the path tests: closed, its faces wound so that the
// geometric normal points outward.
#pragma once

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <vector>

#include "scenes/control_cage.h"

namespace facet::testing {

// A UV sphere of radius 1 about the origin, `rings` x `segments` faces
// (quads, and triangles at the poles), rendered as authored.
inline scene::ControlCage uvSphere(int rings, int segments) {
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

}  // namespace facet::testing

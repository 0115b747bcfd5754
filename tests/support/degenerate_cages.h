#pragma once
// Cages whose patches defeat a surface-area heuristic, rendered as authored
// (one bilinear patch per quad): the inputs of the BVH depth bounds' tests
// (tests/scenes/patch_bvh_test.cpp, tests/engine/gpu_backend/top_levels_test.cpp).

#include "scenes/control_cage.h"
#include "scenes/subdivision_surface.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace facet::scene::testing {

enum class Degenerate {
  AlongALine,      // thousands of thin quads end to end along x
  AllInOnePoint,   // every vertex at the same point
  GeometricSizes,  // end to end along x, each 0.8 times the last
  NestedSizes,     // one centre, each 0.8 times the last
};

inline std::string degenerateName(Degenerate kind) {
  switch (kind) {
    case Degenerate::AlongALine:
      return "AlongALine";
    case Degenerate::AllInOnePoint:
      return "AllInOnePoint";
    case Degenerate::GeometricSizes:
      return "GeometricSizes";
    case Degenerate::NestedSizes:
      return "NestedSizes";
  }
  return "";
}

inline ControlCage degenerateCage(Degenerate kind, int quads) {
  ControlCage cage;
  cage.source = degenerateName(kind);
  double x = 0.0, size = 1.0;
  for (int q = 0; q < quads; ++q) {
    glm::dvec3 lo(x, 0.0, 0.0), hi(x + size, 1e-3 * size, 0.0);
    if (kind == Degenerate::AllInOnePoint) lo = hi = glm::dvec3(1.0, 2.0, 3.0);
    if (kind == Degenerate::NestedSizes) lo = glm::dvec3(-size, -size, 0.0), hi = glm::dvec3(size, size, 0.0);
    const int first = int(cage.positions.size());
    cage.positions.insert(cage.positions.end(), {lo, glm::dvec3(hi.x, lo.y, lo.z), hi, glm::dvec3(lo.x, hi.y, hi.z)});
    cage.faceVertexCounts.push_back(4);
    for (int k = 0; k < 4; ++k) cage.faceVertexIndices.push_back(first + k);
    x += size;
    if (kind == Degenerate::GeometricSizes || kind == Degenerate::NestedSizes) size *= 0.8;
  }
  return cage;
}

inline SubdivisionSurface degenerateSurface(Degenerate kind, int quads) {
  RefinementSettings settings;
  settings.subdivision = Subdivision::None;
  return SubdivisionSurface::create(degenerateCage(kind, quads), settings);
}

}  // namespace facet::scene::testing

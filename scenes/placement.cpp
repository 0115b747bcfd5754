#include "scenes/placement.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace facet::scene {
namespace {

// Each face's corners after its first in reverse order, in one per-corner array.
template <class T>
void reverseWinding(std::vector<T>& corners, const std::vector<int>& faceVertexCounts) {
  if (corners.empty()) return;
  std::size_t first = 0;
  for (int count : faceVertexCounts) {
    std::reverse(corners.begin() + std::ptrdiff_t(first) + 1,
                 corners.begin() + std::ptrdiff_t(first + std::size_t(count)));
    first += std::size_t(count);
  }
}

}  // namespace

void transformCage(ControlCage& cage, const glm::dmat4& matrix) {
  for (glm::dvec3& p : cage.positions) p = glm::dvec3(matrix * glm::dvec4(p, 1.0));
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(matrix)));
  for (glm::dvec3& n : cage.faceVertexNormals) n = glm::normalize(normalMatrix * n);
  // A mirror turns n x t against the mirrored bitangent: the sign flips with it.
  const double handedness = glm::determinant(glm::dmat3(matrix)) < 0 ? -1.0 : 1.0;
  for (glm::dvec4& t : cage.faceVertexTangents)
    t = glm::dvec4(glm::normalize(glm::dmat3(matrix) * glm::dvec3(t)), handedness * t.w);
  if (handedness > 0) return;
  reverseWinding(cage.faceVertexIndices, cage.faceVertexCounts);
  reverseWinding(cage.faceVertexNormals, cage.faceVertexCounts);
  reverseWinding(cage.faceVertexTangents, cage.faceVertexCounts);
  reverseWinding(cage.faceVertexTexcoords, cage.faceVertexCounts);
  reverseWinding(cage.faceVertexTexcoords1, cage.faceVertexCounts);
  reverseWinding(cage.faceVertexColors, cage.faceVertexCounts);
}

Scene turntableFrame(const Scene& scene, int frame, int frames, TurntableTurn turn) {
  const double angle = glm::two_pi<double>() * double(frame) / double(frames);
  Scene turned = scene;
  if (turn == TurntableTurn::Environment) {
    if (!turned.environment)
      throw std::invalid_argument(
          "--turn environment: the scene has no environment map to turn; "
          "turn the model, or give the scene an environment");
    turned.environment->rotationDegrees += glm::degrees(angle);
    return turned;
  }
  const glm::dvec3 pivot = scene.camera.target;
  const glm::dmat4 about = glm::translate(glm::dmat4(1.0), pivot) *
                           glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0, 1, 0)) *
                           glm::translate(glm::dmat4(1.0), -pivot);
  for (Object& object : turned.objects) transformCage(object.cage, about);
  return turned;
}

}  // namespace facet::scene

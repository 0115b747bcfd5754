#include "engine/image/exr_metadata.h"

#include <glm/geometric.hpp>

#include <algorithm>

#include "engine/image/image.h"

namespace facet {
namespace {

RowMatrix product(const RowMatrix& a, const RowMatrix& b) {
  RowMatrix m{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) m[i][j] += a[i][k] * b[k][j];
  return m;
}

}  // namespace

RowMatrix worldToCamera(const ExrCamera& c) {
  RowMatrix m{};
  const glm::dvec3 axes[3] = {c.right, c.up, c.forward};
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) m[i][j] = axes[j][i];
    m[3][j] = -glm::dot(c.eye, axes[j]);
  }
  m[3][3] = 1.0;
  return m;
}

RowMatrix worldToNdc(const ExrCamera& c) {
  // x_ndc = 1/2 + x / (2 z tan aspect), y_ndc = 1/2 - y / (2 z tan): the
  // inverse of camera_ray_direction, with w = z.
  RowMatrix projection{};
  projection[0][0] = 0.5 / (c.tanHalfFovY * c.aspect);
  projection[1][1] = -0.5 / c.tanHalfFovY;
  projection[2][0] = projection[2][1] = 0.5;
  projection[2][3] = 1.0;
  projection[3][2] = 1.0;
  return product(worldToCamera(c), projection);
}

std::uint32_t objectOfFace(const ExrNames& names, std::uint32_t faceId) {
  if (faceId == Image::kNoId) return Image::kNoId;
  const auto after = std::upper_bound(names.firstFace.begin(), names.firstFace.end(), faceId);
  return std::uint32_t(after - names.firstFace.begin()) - 1;
}

}  // namespace facet

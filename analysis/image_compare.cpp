#include "analysis/image_compare.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace facet::analysis {

bool neighbourhoodIs(const Image& image, int x, int y, bool coveredState) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = std::clamp(x + dx, 0, image.width - 1), ny = std::clamp(y + dy, 0, image.height - 1);
      if (covered(image, nx, ny) != coveredState) return false;
    }
  return true;
}

bool onSilhouette(const Image& image, int x, int y) {
  return !neighbourhoodIs(image, x, y, true) && !neighbourhoodIs(image, x, y, false);
}

bool interior(const Image& candidate, const Image& reference, int x, int y) {
  return neighbourhoodIs(candidate, x, y, true) && neighbourhoodIs(reference, x, y, true);
}

bool hole(const Image& candidate, const Image& reference, int x, int y) {
  return !covered(candidate, x, y) && neighbourhoodIs(reference, x, y, true);
}

bool extra(const Image& candidate, const Image& reference, int x, int y) {
  return covered(candidate, x, y) && neighbourhoodIs(reference, x, y, false);
}

bool finitePixel(const Image& image, int x, int y) {
  const std::size_t i = image.index(x, y);
  const glm::vec4& b = image.beauty[i];
  const glm::vec3& n = image.shadingNormal[i];
  return std::isfinite(b.r) && std::isfinite(b.g) && std::isfinite(b.b) && std::isfinite(n.x) && std::isfinite(n.y) &&
         std::isfinite(n.z) && (!covered(image, i) || std::isfinite(image.depth[i]));
}

double depthRelativeError(float candidate, float reference) {
  return std::abs(double(candidate) - double(reference)) / std::abs(double(reference));
}

double normalAngle(const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 da(a), db(b);
  if (glm::length(da) * glm::length(db) == 0) return std::numbers::pi;
  return std::atan2(glm::length(glm::cross(da, db)), glm::dot(da, db));
}

double beautyDifference(const glm::vec4& candidate, const glm::vec4& reference) {
  double difference = 0;
  for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(double(candidate[c]) - double(reference[c])));
  return difference;
}

double beautyFloor(const Image& reference) {
  float brightest = 0;
  for (const glm::vec4& b : reference.beauty) brightest = std::max({brightest, b.r, b.g, b.b});
  return std::max(1e-4 * brightest, 1e-30);
}

double beautyRelativeError(const glm::vec4& candidate, const glm::vec4& reference, double floor) {
  const double scale =
      std::max({std::abs(double(reference.r)), std::abs(double(reference.g)), std::abs(double(reference.b)), floor});
  return beautyDifference(candidate, reference) / scale;
}

float middleGreyExposure(const Image& reference) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i)
    if (covered(reference, i)) {
      const glm::vec4& b = reference.beauty[i];
      sum += (b.r + b.g + b.b) / 3.0;
      ++count;
    }
  const double mean = count ? sum / double(count) : 0;
  return mean > 0 ? float(std::log2(0.18 / mean)) : 0.0f;
}

ImageError compareToReference(const Image& candidate, const Image& reference) {
  if (candidate.width != reference.width || candidate.height != reference.height)
    throw std::invalid_argument("compareToReference: images differ in size");
  ImageError e;
  double squared = 0, sum = 0, depthSum = 0, normalSum = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const std::size_t i = reference.index(x, y);
      if (!finitePixel(candidate, x, y)) {
        ++e.nonFinite;
        continue;
      }
      if (hole(candidate, reference, x, y)) ++e.holes;
      if (extra(candidate, reference, x, y)) ++e.extra;
      if (!covered(candidate, i) || !covered(reference, i)) continue;
      ++e.compared;
      for (int c = 0; c < 3; ++c) {
        const double d = double(candidate.beauty[i][c]) - double(reference.beauty[i][c]);
        squared += d * d;
        sum += reference.beauty[i][c];
      }
      e.maxAbsolute = std::max(e.maxAbsolute, beautyDifference(candidate.beauty[i], reference.beauty[i]));
      const double depth = depthRelativeError(candidate.depth[i], reference.depth[i]);
      e.depthRelativeMax = std::max(e.depthRelativeMax, depth);
      depthSum += depth;
      const double angle = normalAngle(candidate.shadingNormal[i], reference.shadingNormal[i]);
      e.normalRadiansMax = std::max(e.normalRadiansMax, angle);
      normalSum += angle;
    }
  if (e.compared > 0) {
    const double n = double(e.compared);
    e.relativeRmse = sum > 0 ? std::sqrt(squared / (3 * n)) / (sum / (3 * n)) : std::sqrt(squared / (3 * n));
    e.depthRelativeMean = depthSum / n;
    e.normalRadiansMean = normalSum / n;
  }
  return e;
}

DepthError compareDepth(const std::vector<float>& candidate, const std::vector<float>& reference) {
  DepthError e;
  if (reference.empty() || candidate.size() != reference.size()) return e;
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    const bool a = covered(candidate[i]), b = covered(reference[i]);
    if (a != b) ++e.coverageMismatch;
    if (!a || !b) continue;
    const double relative = depthRelativeError(candidate[i], reference[i]);
    sum += relative;
    worst = std::max(worst, relative);
    ++e.bothCovered;
  }
  if (e.bothCovered > 0) {
    e.maxRelative = worst;
    e.meanRelative = sum / double(e.bothCovered);
  }
  return e;
}

double blockRelativeRmse(const Image& a, const Image& b, const Image& coverage, int block) {
  double squares = 0, sum = 0;
  std::size_t blocks = 0, pixels = 0;
  for (int by = 0; by < coverage.height; by += block)
    for (int bx = 0; bx < coverage.width; bx += block) {
      glm::dvec3 sumA(0), sumB(0);
      int count = 0;
      for (int y = by; y < std::min(by + block, coverage.height); ++y)
        for (int x = bx; x < std::min(bx + block, coverage.width); ++x)
          if (covered(coverage, x, y)) {
            sumA += glm::dvec3(a.beauty[a.index(x, y)]), sumB += glm::dvec3(b.beauty[b.index(x, y)]), ++count;
          }
      if (count == 0) continue;
      const glm::dvec3 d = (sumA - sumB) / double(count);
      squares += glm::dot(d, d) / 3, sum += (sumB.r + sumB.g + sumB.b) / 3, pixels += std::size_t(count), ++blocks;
    }
  return blocks == 0 || sum <= 0 ? 0 : std::sqrt(squares / double(blocks)) / (sum / double(pixels));
}

glm::dvec3 coveredMean(const Image& image, const Image& coverage) {
  glm::dvec3 sum(0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < coverage.pixelCount(); ++i)
    if (covered(coverage, i)) sum += glm::dvec3(image.beauty[i]), ++count;
  return count == 0 ? glm::dvec3(0) : sum / double(count);
}

}  // namespace facet::analysis

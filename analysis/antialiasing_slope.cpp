#include "analysis/antialiasing_slope.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/image_compare.h"
#include "analysis/power_law.h"

namespace facet::analysis {
namespace {

struct SquaredErrors {
  double silhouette = 0;
  double smooth = 0;
  std::size_t silhouettePixels = 0;
  std::size_t smoothPixels = 0;
};

// No edge inside the reference's 3 x 3 neighbourhood: all covered, depths
// within 2% of the centre's and shading normals within 25 degrees of it (no
// occlusion boundary, no crease).
bool smoothNeighbourhood(const Image& reference, int x, int y) {
  const std::size_t centre = reference.index(x, y);
  if (!neighbourhoodIs(reference, x, y, true)) return false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const std::size_t i =
          reference.index(std::clamp(x + dx, 0, reference.width - 1), std::clamp(y + dy, 0, reference.height - 1));
      if (std::abs(reference.depth[i] - reference.depth[centre]) > 0.02f * reference.depth[centre] ||
          glm::dot(reference.shadingNormal[i], reference.shadingNormal[centre]) < 0.9f)
        return false;
    }
  return true;
}

// Silhouette: the reference's 3 x 3 neighbourhood holds covered and missed
// pixels; smooth: smoothNeighbourhood. Pixels next to an occlusion boundary
// or a crease are neither.
SquaredErrors squaredErrors(const Image& candidate, const Image& reference) {
  SquaredErrors e;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const std::size_t i = reference.index(x, y);
      const glm::dvec3 d = glm::dvec3(candidate.beauty[i]) - glm::dvec3(reference.beauty[i]);
      const double squared = (d.r * d.r + d.g * d.g + d.b * d.b) / 3;
      if (onSilhouette(reference, x, y)) {
        e.silhouette += squared;
        ++e.silhouettePixels;
      } else if (smoothNeighbourhood(reference, x, y)) {
        e.smooth += squared;
        ++e.smoothPixels;
      }
    }
  return e;
}

double meanCoveredRadiance(const Image& image) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < image.beauty.size(); ++i)
    if (covered(image, i)) {
      sum += (image.beauty[i].r + image.beauty[i].g + image.beauty[i].b) / 3.0;
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

double slopeFromFourSpp(const std::vector<AntialiasingPoint>& points, double AntialiasingPoint::*error) {
  std::vector<double> x, t;
  for (const AntialiasingPoint& p : points)
    if (p.samplesPerPixel >= 4) {
      x.push_back(p.samplesPerPixel);
      t.push_back(p.*error);
    }
  return x.size() < 2 ? NAN : fitPowerLaw(x, t).exponent;
}

}  // namespace

AntialiasingCurve measureAntialiasing(Renderer& renderer, scene::Scene scene, const std::vector<int>& samplesPerPixel,
                                      Backend backend) {
  if (samplesPerPixel.empty() || !scene.environment)
    throw std::invalid_argument("measureAntialiasing: needs sample counts and an environment");
  scene.environment->method = scene::IblMethod::Prefiltered;
  AntialiasingCurve curve;
  // 16 x: the reference's own error then stays near a tenth of the last point's.
  curve.referenceSamples = 16 * samplesPerPixel.back();
  scene.render.samplesPerPixel = curve.referenceSamples;
  const Image reference = renderer.render(scene, backend).image;
  const double mean = meanCoveredRadiance(reference);
  if (mean <= 0) throw std::runtime_error("measureAntialiasing: the reference covers no lit pixel");
  for (int spp : samplesPerPixel) {
    scene.render.samplesPerPixel = spp;
    const SquaredErrors e = squaredErrors(renderer.render(scene, backend).image, reference);
    curve.points.push_back({spp, std::sqrt(e.silhouette / double(std::max<std::size_t>(e.silhouettePixels, 1))) / mean,
                            std::sqrt(e.smooth / double(std::max<std::size_t>(e.smoothPixels, 1))) / mean});
  }
  curve.silhouetteSlope = slopeFromFourSpp(curve.points, &AntialiasingPoint::silhouetteRmse);
  curve.smoothSlope = slopeFromFourSpp(curve.points, &AntialiasingPoint::smoothRmse);
  return curve;
}

}  // namespace facet::analysis

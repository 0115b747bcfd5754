// A render against a reference of the same scene, pixel by pixel: the one
// rule for a covered pixel and the one definition of each error, shared by
// `facet parity`, `facet bench`, `facet ibl-chart` and raycast_bench.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/image/image.h"

namespace facet::analysis {

// A pixel is covered where the camera ray through its centre hit a surface.
// That ray gives every AOV (depth, normals, ids), and parity's tolerances are
// stated on it (docs/rendering.md, "Parity"); a hit is marked by a patch id.
// Alpha is not the test: with several samples per pixel it is the share of
// samples that hit, above 0 on pixels whose centre ray missed.
inline bool covered(const Image& image, std::size_t pixel) { return image.patchId[pixel] != Image::kNoId; }
inline bool covered(const Image& image, int x, int y) { return covered(image, image.index(x, y)); }
// The same rule on an image of depth alone (a peer's): +inf where the ray missed.
inline bool covered(float depth) { return std::isfinite(depth); }

// Every pixel of the 3 x 3 neighbourhood (clamped at the border) covered, or
// every one missed (`coveredState` false).
bool neighbourhoodIs(const Image& image, int x, int y, bool coveredState);
// The 3 x 3 neighbourhood holds both covered and missed pixels.
bool onSilhouette(const Image& image, int x, int y);
// Covered on both images and on a silhouette of neither: where depth,
// normals and beauty are held to their tolerances.
bool interior(const Image& candidate, const Image& reference, int x, int y);
// Covered here, and all 8 neighbours too, on `reference`, missed on `candidate`.
bool hole(const Image& candidate, const Image& reference, int x, int y);
// Covered on `candidate` where `reference` misses the pixel and its 8 neighbours.
bool extra(const Image& candidate, const Image& reference, int x, int y);
// Beauty and shading normal finite, and the depth where the pixel is covered.
bool finitePixel(const Image& image, int x, int y);

// |dz| / z.
double depthRelativeError(float candidate, float reference);
// Angle between two normals (atan2 of |a x b| and a.b, exact at small
// angles); a zero-length one (float underflow far from unit scale) has no
// direction and counts as the worst angle, pi.
double normalAngle(const glm::vec3& a, const glm::vec3& b);
// Largest RGB channel difference.
double beautyDifference(const glm::vec4& candidate, const glm::vec4& reference);
// The scale below which a beauty error is judged absolutely: 1e-4 of the
// reference's brightest channel, so black pixels compare at a level far
// below 8-bit output.
double beautyFloor(const Image& reference);
// beautyDifference / max(brightest channel of the reference pixel, floor).
double beautyRelativeError(const glm::vec4& candidate, const glm::vec4& reference, double floor);

// The PNG exposure, in stops, that puts the reference's mean covered
// radiance at middle grey (0.18): one exposure for every render of a scene.
float middleGreyExposure(const Image& reference);

struct ImageError {
  double relativeRmse = 0;      // beauty RGB over pixels covered on both, / the reference's mean there
  double maxAbsolute = 0;       // beauty, largest channel difference, same pixels
  double depthRelativeMax = 0;  // over pixels covered on both
  double depthRelativeMean = 0;
  double normalRadiansMax = 0;  // shading normal, same pixels
  double normalRadiansMean = 0;
  std::size_t holes = 0;
  std::size_t extra = 0;
  std::size_t nonFinite = 0;  // NaN or Inf in beauty, depth or normal of the candidate
  std::size_t compared = 0;   // pixels covered on both
};
ImageError compareToReference(const Image& candidate, const Image& reference);

// Mean beauty per channel over the pixels `coverage` covers (0 where none is).
glm::dvec3 coveredMean(const Image& image, const Image& coverage);

// Relative RMSE of `a` against `b` over blocks of block x block pixels,
// each block the mean of the pixels `coverage` covers (blocks without any
// are left out), relative to b's mean over the covered pixels; 0 where
// nothing is covered. Blocks trade resolution for noise: a bias that spans
// a block stays, independent noise falls by the square root of the pixels
// averaged. With block 1 it is compareToReference's relative RMSE.
double blockRelativeRmse(const Image& a, const Image& b, const Image& coverage, int block);

// Depth images alone (peers that only cast rays); NaN errors when nothing is compared.
struct DepthError {
  double maxRelative = NAN;
  double meanRelative = NAN;
  std::size_t bothCovered = 0;
  std::size_t coverageMismatch = 0;  // covered in one image only
};
DepthError compareDepth(const std::vector<float>& candidate, const std::vector<float>& reference);

}  // namespace facet::analysis

// Parity of stochastic estimators (sampled or filtered image-based lighting,
// paths with bounces): both backends render the scene k times, render i of
// each with the same seed, so that they draw the same random numbers and
// their difference is what float and double decided differently plus any
// bias. Per pixel and channel, the mean of the k differences is tested
// against zero by a paired t-test (the difference beyond the deterministic
// tolerance, over its standard error), at a level Sidak-corrected for the
// number of tests; the image passes when a stated share of pixels do
// (Mitsuba's render tests; docs/parity.md).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/image/image.h"

namespace facet::analysis {

// Per pixel and beauty channel, running sums over pairs of renders.
class PairedRenders {
 public:
  // The first pair's images keep every AOV (they do not depend on the seed);
  // later pairs add their beauty. Throws std::invalid_argument on a size
  // that differs.
  void add(const Image& reference, const Image& candidate);

  int count() const { return count_; }
  // The first pair's images with the mean beauty of every pair.
  Image referenceMean() const;
  Image candidateMean() const;
  // Per channel, the variance of the mean difference: the paired test's
  // squared standard error.
  glm::dvec3 meanDifferenceVariance(std::size_t pixel) const;

 private:
  Image mean(const Image& first, const std::vector<glm::dvec3>& sum) const;
  int count_ = 0;
  Image firstReference_, firstCandidate_;
  std::vector<glm::dvec3> sumReference_, sumCandidate_, sumDifference_, squaresDifference_;
};

// Two-sided p-value of Student's t with `dof` degrees of freedom; a t of
// +inf gives 0.
double studentTwoSidedP(double t, double dof);

// The level at which each of `tests` independent tests is run so that any of
// them fails by chance with probability `alpha`: 1 - (1 - alpha)^(1/tests).
double sidakAlpha(double alpha, std::size_t tests);

}  // namespace facet::analysis

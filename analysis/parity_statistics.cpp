#include "analysis/parity_statistics.h"

#include <glm/common.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace facet::analysis {
namespace {

glm::dvec3 rgb(const glm::vec4& beauty) { return {beauty.r, beauty.g, beauty.b}; }

// The continued fraction of the incomplete beta function, by the modified
// Lentz method (Numerical Recipes, 3rd edition, 6.4).
double betaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300, kEpsilon = 1e-15;
  const double qab = a + b, qap = a + 1, qam = a - 1;
  auto guarded = [](double v) { return std::abs(v) < kTiny ? kTiny : v; };
  double c = 1, d = 1 / guarded(1 - qab * x / qap), h = d;
  for (int m = 1; m <= 1000; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1 / guarded(1 + aa * d);
    c = guarded(1 + aa / c);
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1 / guarded(1 + aa * d);
    c = guarded(1 + aa / c);
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1) < kEpsilon) break;
  }
  return h;
}

// The regularized incomplete beta function I_x(a, b).
double incompleteBeta(double a, double b, double x) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2)) return front * betaContinuedFraction(a, b, x) / a;
  return 1 - front * betaContinuedFraction(b, a, 1 - x) / b;
}

}  // namespace

void PairedRenders::add(const Image& reference, const Image& candidate) {
  if (reference.width != candidate.width || reference.height != candidate.height ||
      (count_ > 0 && (reference.width != firstReference_.width || reference.height != firstReference_.height)))
    throw std::invalid_argument("parity: renders differ in size");
  const std::size_t pixels = reference.pixelCount();
  if (count_ == 0) {
    firstReference_ = reference;
    firstCandidate_ = candidate;
    for (auto* sums : {&sumReference_, &sumCandidate_, &sumDifference_, &squaresDifference_})
      sums->assign(pixels, glm::dvec3(0));
  }
  for (std::size_t p = 0; p < pixels; ++p) {
    const glm::dvec3 a = rgb(reference.beauty[p]), b = rgb(candidate.beauty[p]), d = b - a;
    sumReference_[p] += a;
    sumCandidate_[p] += b;
    sumDifference_[p] += d;
    squaresDifference_[p] += d * d;
  }
  ++count_;
}

Image PairedRenders::mean(const Image& first, const std::vector<glm::dvec3>& sum) const {
  Image image = first;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    const glm::dvec3 m = sum[p] / double(count_);
    image.beauty[p] = {float(m.r), float(m.g), float(m.b), first.beauty[p].a};
  }
  return image;
}

Image PairedRenders::referenceMean() const { return mean(firstReference_, sumReference_); }
Image PairedRenders::candidateMean() const { return mean(firstCandidate_, sumCandidate_); }

namespace {
// Unbiased sample variance from sums; rounding can leave it a hair below 0.
glm::dvec3 sampleVariance(const glm::dvec3& sum, const glm::dvec3& squares, int n) {
  if (n < 2) return glm::dvec3(std::numeric_limits<double>::infinity());
  const glm::dvec3 mean = sum / double(n);
  return glm::max((squares - double(n) * mean * mean) / double(n - 1), glm::dvec3(0));
}
}  // namespace

glm::dvec3 PairedRenders::meanDifferenceVariance(std::size_t p) const {
  return sampleVariance(sumDifference_[p], squaresDifference_[p], count_) / double(count_);
}

double studentTwoSidedP(double t, double dof) {
  if (!std::isfinite(t)) return 0;  // NaN: a difference that is not a number is no agreement
  return incompleteBeta(dof / 2, 0.5, dof / (dof + t * t));
}

double sidakAlpha(double alpha, std::size_t tests) {
  return tests == 0 ? alpha : -std::expm1(std::log1p(-alpha) / double(tests));
}

}  // namespace facet::analysis

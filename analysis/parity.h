// GPU-CPU parity: an image compared with the CPU reference's, AOV by AOV,
// under the tolerances and pass rules of docs/parity.md. Covered, silhouette
// and interior pixels and each error are those of analysis/image_compare.h.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/image.h"

namespace facet::analysis {

class PairedRenders;

// A pixel is within tolerance when |candidate - reference| <= absolute +
// relative * |reference|, and the AOV passes when at least `passShare` of the
// pixels it judges are (rounded up to whole pixels: on a small image 0.1% is
// less than one pixel, and one pixel is what the rule then allows).
struct Tolerance {
  double absolute = 0;
  double relative = 0;
  double passShare = 1;
  bool interiorOnly = true;  // judged off silhouettes only; else on every pixel covered on both

  double at(double reference) const { return absolute + relative * std::abs(reference); }
};

struct ParityTolerances {
  double coverageShare = 1e-3;   // silhouette pixels whose coverage may differ, of all pixels
  std::size_t minCoverage = 16;  // pixels covered on both below which nothing is judged
  Tolerance depth{0, 1e-4, 1, true};
  Tolerance normal{1e-3, 0, 1, true};  // radians; a normal has no magnitude to be relative to
  // Its absolute part when none is given: this share of the brightest
  // channel of the reference's covered pixels, below one step of 8-bit sRGB
  // output at any exposure that does not clip that channel.
  Tolerance beauty{0, 1e-3, 0.999, false};
  std::optional<double> beautyAbsolute;
  double beautyAbsoluteOfBrightest = 1e-4;
  // The statistical test on stochastic beauty (parity_statistics.h).
  double significance = 0.01;  // before the Sidak correction over every pixel and channel
  double statisticalShare = 0.9975;
};

enum class Verdict { Pass, Fail, InsufficientCoverage };
const char* toString(Verdict verdict);

struct WorstPixel {
  int x = 0, y = 0;
  double reference = 0, candidate = 0;  // the AOV's value (beauty: the worst channel; normals: 0 and the angle)
  double error = 0;                     // in units of the tolerance where gated, else the AOV's own error
};

// One AOV over the pixels covered on both images.
struct AovParity {
  std::string name;
  std::string unit;  // what "relative" means for it
  bool gated = false;
  std::string test;  // "tolerance" or "paired t-test" where gated
  Tolerance tolerance;
  double maxAbsolute = 0;
  double meanAbsolute = 0;
  double maxRelative = 0;  // angles in radians for normals
  double meanRelative = 0;
  std::size_t judged = 0;          // pixels the rule counts
  std::size_t overSilhouette = 0;  // gated: pixels over tolerance
  std::size_t overInterior = 0;
  std::size_t allowed = 0;  // over tolerance that the pass rule allows
  std::size_t over() const { return overInterior + (tolerance.interiorOnly ? 0 : overSilhouette); }  // of the judged
  double shareOver = 0;  // of the judged pixels
  // The paired t-test: its significance, the Sidak-corrected level each
  // pixel's channels are tested at, the smallest p-value, and the renders
  // per backend.
  double significance = 0, alpha = 0, minPValue = 1;
  int renders = 0;
  std::vector<WorstPixel> worst;  // largest error first
  bool pass = true;               // always true where not gated
  // Gated: per pixel, the error in units of the tolerance (the t-test's:
  // log p / log alpha); -1 where coverage differs, 0 where both miss.
  std::vector<float> heat;
};

struct ParityReport {
  int width = 0;
  int height = 0;
  std::size_t pixels = 0;
  std::size_t covered = 0;  // on both
  std::size_t minCoverage = 0;
  std::size_t silhouettePixels = 0;
  std::size_t coverageMismatches = 0;          // all of them
  std::size_t coverageMismatchesInterior = 0;  // not on a silhouette: always a failure
  std::size_t coverageAllowed = 0;
  bool coveragePass = true;
  std::vector<AovParity> aovs;
  Verdict verdict = Verdict::Pass;
  bool pass = true;  // verdict == Pass
  // Per pixel, the largest of the gated AOVs' heat.
  std::vector<float> heat;
};

// With `renders` of at least two pairs, beauty is judged by the paired
// t-test of parity_statistics.h and `reference` and `candidate` are
// expected to carry the renders' mean beauty.
ParityReport compareImages(const Image& reference, const Image& candidate, const ParityTolerances& tolerances = {},
                           const PairedRenders* renders = nullptr);

// A gated AOV's rule in words, with its numbers: "|d| <= 0 + 1.0e-04 |ref|
// on 100% of interior pixels"; "not gated" for the others.
std::string passRule(const AovParity& aov);

// A table for people, one AOV a line, with every gated AOV's rule.
std::string describe(const ParityReport& report);

}  // namespace facet::analysis

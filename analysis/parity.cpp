#include "analysis/parity.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "analysis/image_compare.h"
#include "analysis/parity_statistics.h"

namespace facet::analysis {
namespace {

constexpr std::size_t kWorstPixels = 5;

// Shares are rounded up to whole pixels (Tolerance).
std::size_t allowance(double share, std::size_t of) { return std::size_t(std::ceil(share * double(of) - 1e-9)); }

struct Accumulator {
  AovParity aov;
  std::size_t count = 0;
  std::size_t width = 0;

  void record(double absolute, double relative) {
    ++count;
    aov.maxAbsolute = std::max(aov.maxAbsolute, absolute);
    aov.meanAbsolute += absolute;
    aov.maxRelative = std::max(aov.maxRelative, relative);
    aov.meanRelative += relative;
  }

  // `relative` is only reported; a gated AOV is judged on `absolute`
  // against its tolerance at `scale`, the reference's magnitude.
  void add(double absolute, double relative, double scale, bool onSilhouette, const WorstPixel& where) {
    record(absolute, relative);
    if (!aov.gated) {
      keepWorst({where.x, where.y, where.reference, where.candidate, absolute});
      return;
    }
    const double bound = aov.tolerance.at(scale);
    judge(bound > 0 ? absolute / bound : absolute == 0 ? 0.0 : INFINITY, onSilhouette, where);
  }

  // A pixel's error in units of its tolerance (NaN: over).
  void judge(double units, bool onSilhouette, const WorstPixel& where) {
    aov.heat[std::size_t(where.y) * width + std::size_t(where.x)] = std::isnan(units) ? INFINITY : float(units);
    if (!aov.tolerance.interiorOnly || !onSilhouette) ++aov.judged;
    if (!(units <= 1)) ++(onSilhouette ? aov.overSilhouette : aov.overInterior);
    keepWorst({where.x, where.y, where.reference, where.candidate, std::isnan(units) ? INFINITY : units});
  }

  void keepWorst(const WorstPixel& pixel) {
    if (aov.worst.size() == kWorstPixels && !(pixel.error > aov.worst.back().error)) return;
    auto at =
        std::find_if(aov.worst.begin(), aov.worst.end(), [&](const WorstPixel& w) { return pixel.error > w.error; });
    aov.worst.insert(at, pixel);
    if (aov.worst.size() > kWorstPixels) aov.worst.pop_back();
  }

  AovParity finish() {
    if (count > 0) {
      aov.meanAbsolute /= double(count);
      aov.meanRelative /= double(count);
    }
    if (!aov.gated) return std::move(aov);
    aov.allowed = allowance(1.0 - aov.tolerance.passShare, aov.judged);
    aov.shareOver = aov.judged > 0 ? double(aov.over()) / double(aov.judged) : 0;
    aov.pass = aov.over() <= aov.allowed;
    return std::move(aov);
  }
};

Accumulator gated(const std::string& name, const std::string& unit, const Tolerance& tolerance, const Image& image) {
  Accumulator a;
  a.width = std::size_t(image.width);
  a.aov.heat.assign(image.pixelCount(), 0.0f);
  a.aov.name = name;
  a.aov.unit = unit;
  a.aov.gated = true;
  a.aov.test = "tolerance";
  a.aov.tolerance = tolerance;
  return a;
}

Accumulator reported(const std::string& name, const std::string& unit) {
  Accumulator a;
  a.aov.name = name;
  a.aov.unit = unit;
  return a;
}

std::size_t coveredOnBoth(const Image& reference, const Image& candidate) {
  std::size_t count = 0;
  for (std::size_t p = 0; p < reference.pixelCount(); ++p) count += covered(reference, p) && covered(candidate, p);
  return count;
}

// Of the covered pixels: the environment a miss sees can be far brighter
// than any surface (a sun), and would loosen the floor on every surface.
double brightestCovered(const Image& image) {
  float brightest = 0;
  for (std::size_t p = 0; p < image.pixelCount(); ++p)
    if (covered(image, p)) brightest = std::max({brightest, image.beauty[p].r, image.beauty[p].g, image.beauty[p].b});
  return brightest;
}

double brightestChannel(const glm::vec4& b) {
  return std::max({std::abs(double(b.r)), std::abs(double(b.g)), std::abs(double(b.b))});
}

// The paired t-test's verdict on one pixel's beauty, in units of its level:
// log p / log alpha, above 1 where some channel's p-value is below alpha.
double beautyTestUnits(const PairedRenders& renders, std::size_t p, const glm::vec4& reference,
                       const glm::vec4& candidate, double bound, double alpha, double& minPValue) {
  const glm::dvec3 variance = renders.meanDifferenceVariance(p);
  double worst = 1;
  for (int c = 0; c < 3; ++c) {
    const double difference = std::abs(double(candidate[c]) - double(reference[c]));
    const double excess = std::max(0.0, difference - bound);
    const double t = variance[c] > 0 ? excess / std::sqrt(variance[c]) : excess > 0 ? INFINITY : 0.0;
    worst = std::min(worst, std::isnan(difference) ? 0.0 : studentTwoSidedP(t, renders.count() - 1));
  }
  minPValue = std::min(minPValue, worst);
  return worst > 0 ? std::log(worst) / std::log(alpha) : INFINITY;
}

// The AOVs that are reported and gate nothing, accumulated pixel by pixel.
struct ReportedAovs {
  Accumulator alpha = reported("alpha", "|d|");
  Accumulator position = reported("position", "|dP| / |P|");
  Accumulator geometric = reported("geometric normal", "angle (rad)");
  Accumulator uv = reported("uv", "|duv|");
  Accumulator texcoord = reported("texcoord", "|dst|");
  Accumulator patchId = reported("patchId", "differs");
  Accumulator faceId = reported("faceId", "differs");

  // Pixel (x, y), covered on both images.
  void add(const Image& reference, const Image& candidate, int x, int y, bool onEitherSilhouette) {
    const std::size_t p = reference.index(x, y);
    const glm::vec4 &rb = reference.beauty[p], &cb = candidate.beauty[p];
    const double da = std::abs(double(cb.a) - double(rb.a));
    alpha.add(da, da, 0, onEitherSilhouette, {x, y, rb.a, cb.a});
    const glm::dvec3 rp(reference.position[p]), cp(candidate.position[p]);
    const double dp = glm::length(cp - rp);
    position.add(dp, dp / std::max(glm::length(rp), 1e-30), 0, onEitherSilhouette,
                 {x, y, glm::length(rp), glm::length(cp)});
    const double geometricAngle = normalAngle(reference.geometricNormal[p], candidate.geometricNormal[p]);
    geometric.add(geometricAngle, geometricAngle, 0, onEitherSilhouette, {x, y, 0, geometricAngle});
    const double duv = glm::length(glm::dvec2(candidate.uv[p]) - glm::dvec2(reference.uv[p]));
    uv.add(duv, duv, 0, onEitherSilhouette, {x, y, 0, duv});
    const double dst = glm::length(glm::dvec2(candidate.texcoord[p]) - glm::dvec2(reference.texcoord[p]));
    texcoord.add(dst, dst, 0, onEitherSilhouette, {x, y, 0, dst});
    const double patchDiffers = reference.patchId[p] != candidate.patchId[p] ? 1.0 : 0.0;
    patchId.add(patchDiffers, patchDiffers, 0, onEitherSilhouette,
                {x, y, double(reference.patchId[p]), double(candidate.patchId[p])});
    const double faceDiffers = reference.faceId[p] != candidate.faceId[p] ? 1.0 : 0.0;
    faceId.add(faceDiffers, faceDiffers, 0, onEitherSilhouette,
               {x, y, double(reference.faceId[p]), double(candidate.faceId[p])});
  }
};

// The verdict from the coverage and the finished AOVs.
void setVerdict(ParityReport& report, std::size_t minCoverage) {
  bool allPass = report.coveragePass;
  for (const AovParity& aov : report.aovs) allPass = allPass && aov.pass;
  // Nothing to judge is no evidence of agreement: an empty image never
  // passes. Coverage that differs is judged first: a candidate that renders
  // nothing where the reference has a surface is wrong, not unjudged.
  const bool enough = report.covered > 0 && report.covered >= minCoverage;
  report.verdict = !report.coveragePass ? Verdict::Fail
                   : !enough            ? Verdict::InsufficientCoverage
                   : allPass            ? Verdict::Pass
                                        : Verdict::Fail;
  if (report.verdict == Verdict::InsufficientCoverage)
    for (AovParity& aov : report.aovs) aov.pass = !aov.gated;
  report.pass = report.verdict == Verdict::Pass;
}

}  // namespace

const char* toString(Verdict verdict) {
  switch (verdict) {
    case Verdict::Pass:
      return "pass";
    case Verdict::Fail:
      return "fail";
    case Verdict::InsufficientCoverage:
      return "insufficient coverage";
  }
  return "?";
}

ParityReport compareImages(const Image& reference, const Image& candidate, const ParityTolerances& tolerances,
                           const PairedRenders* renders) {
  if (reference.width != candidate.width || reference.height != candidate.height)
    throw std::invalid_argument("parity: images differ in size (" + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + " vs " + std::to_string(candidate.width) + "x" +
                                std::to_string(candidate.height) + ")");
  ParityReport report;
  report.width = reference.width;
  report.height = reference.height;
  report.pixels = reference.pixelCount();
  report.minCoverage = tolerances.minCoverage;

  Tolerance beautyTolerance = tolerances.beauty;
  beautyTolerance.absolute =
      tolerances.beautyAbsolute.value_or(tolerances.beautyAbsoluteOfBrightest * brightestCovered(reference));
  const bool statistical = renders && renders->count() >= 2;
  if (statistical) beautyTolerance.passShare = tolerances.statisticalShare;
  Accumulator depth = gated("depth", "|dz| / z", tolerances.depth, reference);
  Accumulator normal = gated("shading normal", "angle (rad)", tolerances.normal, reference);
  Accumulator beauty = gated("beauty", "max_c |d| / max_c |ref|", beautyTolerance, reference);
  if (statistical) {
    beauty.aov.test = "paired t-test";
    beauty.aov.renders = renders->count();
    beauty.aov.significance = tolerances.significance;
    beauty.aov.alpha = sidakAlpha(tolerances.significance, 3 * coveredOnBoth(reference, candidate));
  }
  ReportedAovs others;

  for (int y = 0; y < report.height; ++y) {
    for (int x = 0; x < report.width; ++x) {
      const std::size_t p = reference.index(x, y);
      const bool onEitherSilhouette = onSilhouette(reference, x, y) || onSilhouette(candidate, x, y);
      if (onEitherSilhouette) ++report.silhouettePixels;
      const bool a = covered(reference, p), b = covered(candidate, p);
      if (a != b) {
        ++report.coverageMismatches;
        if (!onEitherSilhouette) ++report.coverageMismatchesInterior;
        for (Accumulator* g : {&depth, &normal, &beauty}) g->aov.heat[p] = -1.0f;
        continue;
      }
      if (!a) continue;
      ++report.covered;
      const float rz = reference.depth[p], cz = candidate.depth[p];
      const double dz = std::abs(double(cz) - double(rz));
      depth.add(dz, depthRelativeError(cz, rz), rz, onEitherSilhouette, {x, y, rz, cz});
      const double angle = normalAngle(reference.shadingNormal[p], candidate.shadingNormal[p]);
      normal.add(angle, angle, 0, onEitherSilhouette, {x, y, 0, angle});
      const glm::vec4 &rb = reference.beauty[p], &cb = candidate.beauty[p];
      const double db = beautyDifference(cb, rb), scale = brightestChannel(rb);
      const WorstPixel beautyAt{x, y, scale, brightestChannel(cb)};
      if (statistical) {
        beauty.record(db, db / std::max(scale, 1e-30));
        const double units =
            beautyTestUnits(*renders, p, rb, cb, beautyTolerance.at(scale), beauty.aov.alpha, beauty.aov.minPValue);
        beauty.judge(units, onEitherSilhouette, beautyAt);
      } else {
        beauty.add(db, db / std::max(scale, 1e-30), scale, onEitherSilhouette, beautyAt);
      }
      others.add(reference, candidate, x, y, onEitherSilhouette);
    }
  }

  report.heat = depth.aov.heat;
  for (std::size_t p = 0; p < report.pixels; ++p)
    if (report.heat[p] >= 0) report.heat[p] = std::max({report.heat[p], normal.aov.heat[p], beauty.aov.heat[p]});
  report.coverageAllowed = allowance(tolerances.coverageShare, report.pixels);
  report.coveragePass = report.coverageMismatchesInterior == 0 && report.coverageMismatches <= report.coverageAllowed;
  for (Accumulator* a : {&depth, &normal, &beauty, &others.alpha, &others.position, &others.geometric, &others.uv,
                         &others.texcoord, &others.patchId, &others.faceId})
    report.aovs.push_back(a->finish());
  setVerdict(report, tolerances.minCoverage);
  return report;
}

namespace {

std::string format(const char* pattern, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

std::string percent(double share) { return format("%.6g%%", 100 * share); }

}  // namespace

std::string passRule(const AovParity& a) {
  if (!a.gated) return "not gated";
  const std::string bound = format("%.1e + %.1e |ref|", a.tolerance.absolute, a.tolerance.relative);
  const std::string pixels = a.tolerance.interiorOnly ? "interior pixels" : "covered pixels";
  if (a.test == "tolerance") return "|d| <= " + bound + " on " + percent(a.tolerance.passShare) + " of " + pixels;
  return format("paired t-test over %d renders of |d| beyond ", a.renders) + bound +
         format(": p >= %.2e (%.2g, Sidak-corrected) on ", a.alpha, a.significance) + percent(a.tolerance.passShare) +
         " of " + pixels;
}

std::string describe(const ParityReport& report) {
  std::string out = format("%dx%d: %zu pixels covered on both (%zu needed to judge), %zu silhouette pixels\n",
                           report.width, report.height, report.covered, report.minCoverage, report.silhouettePixels);
  out +=
      format("coverage: %zu pixels differ, %zu off silhouettes (rule: none off silhouettes, at most %zu on them) %s\n",
             report.coverageMismatches, report.coverageMismatchesInterior, report.coverageAllowed,
             report.coveragePass ? "ok" : "FAIL");
  out += format("%-17s %10s %10s %10s %10s %8s %8s %8s  %s\n", "AOV", "max abs", "mean abs", "max rel", "mean rel",
                "judged", "over", "allowed", "verdict: rule");
  for (const AovParity& a : report.aovs) {
    const std::string counts =
        a.gated ? format("%8zu %8zu %8zu", a.judged, a.over(), a.allowed) : format("%8s %8s %8s", "-", "-", "-");
    out += format("%-17s %10.3e %10.3e %10.3e %10.3e %s  %s: %s (relative is %s)\n", a.name.c_str(), a.maxAbsolute,
                  a.meanAbsolute, a.maxRelative, a.meanRelative, counts.c_str(),
                  !a.gated                                          ? "reported"
                  : report.verdict == Verdict::InsufficientCoverage ? "not judged"
                  : a.pass                                          ? "ok"
                                                                    : "FAIL",
                  passRule(a).c_str(), a.unit.c_str());
    if (a.gated && !a.worst.empty() && a.worst.front().error > 0)
      out += format("%-17s worst at (%d, %d): %.3g x tolerance\n", "", a.worst.front().x, a.worst.front().y,
                    a.worst.front().error);
  }
  switch (report.verdict) {
    case Verdict::Pass:
      return out + "parity: within tolerance\n";
    case Verdict::Fail:
      return out + "parity: OUT OF TOLERANCE\n";
    case Verdict::InsufficientCoverage:
      return out + format(
                       "parity: INSUFFICIENT COVERAGE: %zu pixels covered on both, fewer than the %zu needed to "
                       "judge (--min-coverage)\n",
                       report.covered, std::max<std::size_t>(report.minCoverage, 1));
  }
  return out;
}

}  // namespace facet::analysis
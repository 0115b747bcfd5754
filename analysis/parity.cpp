#include "analysis/parity.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/image_compare.h"
#include "engine/image/image_io.h"

namespace facet::analysis {
namespace {

struct Accumulator {
  AovParity aov;
  std::size_t count = 0;

  // `relative` is compared with the tolerance.
  void add(double absolute, double relative, bool onSilhouette, std::vector<float>& heat, std::size_t pixel) {
    ++count;
    aov.maxAbsolute = std::max(aov.maxAbsolute, absolute);
    aov.meanAbsolute += absolute;
    aov.maxRelative = std::max(aov.maxRelative, relative);
    aov.meanRelative += relative;
    if (aov.tolerance <= 0) return;
    heat[pixel] = std::max(heat[pixel], float(relative / aov.tolerance));
    if (!(relative <= aov.tolerance)) ++(onSilhouette ? aov.overSilhouette : aov.overInterior);
  }

  AovParity finish() {
    if (count > 0) {
      aov.meanAbsolute /= double(count);
      aov.meanRelative /= double(count);
      aov.shareOver = double(aov.overSilhouette + aov.overInterior) / double(count);
    }
    return aov;
  }
};

}  // namespace

ParityReport compareImages(const Image& reference, const Image& candidate, const ParityTolerances& tolerances) {
  if (reference.width != candidate.width || reference.height != candidate.height)
    throw std::invalid_argument("parity: images differ in size (" + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + " vs " + std::to_string(candidate.width) + "x" +
                                std::to_string(candidate.height) + ")");
  ParityReport report;
  report.width = reference.width;
  report.height = reference.height;
  report.pixels = reference.pixelCount();
  report.heat.assign(report.pixels, 0.0f);

  const double floor = beautyFloor(reference);

  Accumulator depth{{"depth", "|dz| / z", 0, 0, 0, 0, tolerances.depthRelative}};
  Accumulator normal{{"shading normal", "angle (rad)", 0, 0, 0, 0, tolerances.normalRadians}};
  Accumulator beauty{{"beauty", "max_c |d| / max(ref)", 0, 0, 0, 0, tolerances.beautyRelative}};
  Accumulator alpha{{"alpha", "|d|", 0, 0, 0, 0, 0}};
  Accumulator position{{"position", "|dP| / |P|", 0, 0, 0, 0, 0}};
  Accumulator geometric{{"geometric normal", "angle (rad)", 0, 0, 0, 0, 0}};
  Accumulator uv{{"uv", "|duv|", 0, 0, 0, 0, 0}};
  Accumulator texcoord{{"texcoord", "|dst|", 0, 0, 0, 0, 0}};
  Accumulator patchId{{"patchId", "differs", 0, 0, 0, 0, 0}};
  Accumulator faceId{{"faceId", "differs", 0, 0, 0, 0, 0}};

  for (int y = 0; y < report.height; ++y) {
    for (int x = 0; x < report.width; ++x) {
      const std::size_t p = reference.index(x, y);
      const bool onEitherSilhouette = onSilhouette(reference, x, y) || onSilhouette(candidate, x, y);
      if (onEitherSilhouette) ++report.silhouettePixels;
      const bool a = covered(reference, p), b = covered(candidate, p);
      if (a != b) {
        ++report.coverageMismatches;
        if (!onEitherSilhouette) ++report.coverageMismatchesInterior;
        report.heat[p] = -1.0f;
        continue;
      }
      if (!a) continue;
      ++report.covered;
      const double dz = std::abs(double(candidate.depth[p]) - double(reference.depth[p]));
      depth.add(dz, depthRelativeError(candidate.depth[p], reference.depth[p]), onEitherSilhouette, report.heat, p);
      const double angle = normalAngle(reference.shadingNormal[p], candidate.shadingNormal[p]);
      normal.add(angle, angle, onEitherSilhouette, report.heat, p);
      const glm::vec4 &rb = reference.beauty[p], &cb = candidate.beauty[p];
      beauty.add(beautyDifference(cb, rb), beautyRelativeError(cb, rb, floor), onEitherSilhouette, report.heat, p);
      const double da = std::abs(double(cb.a) - double(rb.a));
      alpha.add(da, da, onEitherSilhouette, report.heat, p);
      const glm::dvec3 rp(reference.position[p]), cp(candidate.position[p]);
      const double dp = glm::length(cp - rp);
      position.add(dp, dp / std::max(glm::length(rp), 1e-30), onEitherSilhouette, report.heat, p);
      const double geometricAngle = normalAngle(reference.geometricNormal[p], candidate.geometricNormal[p]);
      geometric.add(geometricAngle, geometricAngle, onEitherSilhouette, report.heat, p);
      const double duv = glm::length(glm::dvec2(candidate.uv[p]) - glm::dvec2(reference.uv[p]));
      uv.add(duv, duv, onEitherSilhouette, report.heat, p);
      const double dst = glm::length(glm::dvec2(candidate.texcoord[p]) - glm::dvec2(reference.texcoord[p]));
      texcoord.add(dst, dst, onEitherSilhouette, report.heat, p);
      const double patchDiffers = reference.patchId[p] != candidate.patchId[p] ? 1.0 : 0.0;
      patchId.add(patchDiffers, patchDiffers, onEitherSilhouette, report.heat, p);
      const double faceDiffers = reference.faceId[p] != candidate.faceId[p] ? 1.0 : 0.0;
      faceId.add(faceDiffers, faceDiffers, onEitherSilhouette, report.heat, p);
    }
  }

  // Shares are rounded up to whole pixels: on a small test image 0.1% is
  // less than one pixel, and one pixel is what the bound then allows.
  auto allowance = [](double share, std::size_t of) { return std::size_t(std::ceil(share * double(of))); };
  report.coveragePass = report.coverageMismatchesInterior == 0 &&
                        report.coverageMismatches <= allowance(tolerances.coverageShare, report.pixels);
  for (Accumulator* gated : {&depth, &normal}) gated->aov.pass = gated->aov.overInterior == 0;
  beauty.aov.pass =
      beauty.aov.overSilhouette + beauty.aov.overInterior <= allowance(1.0 - tolerances.beautyShare, beauty.count);
  for (Accumulator* a : {&depth, &normal, &beauty, &alpha, &position, &geometric, &uv, &texcoord, &patchId, &faceId})
    report.aovs.push_back(a->finish());
  report.pass = report.coveragePass;
  for (const AovParity& aov : report.aovs) report.pass = report.pass && aov.pass;
  return report;
}

void writeHeatmap(const std::filesystem::path& path, const ParityReport& report) {
  Image heatmap(report.width, report.height);
  for (std::size_t p = 0; p < report.pixels; ++p) {
    const float e = report.heat[p];
    glm::vec3 colour;
    if (e < 0.0f)
      colour = {0.0f, 0.2f, 1.0f};  // coverage differs
    else if (e <= 1.0f)
      colour = {0.0f, e, 0.0f};
    else
      colour = {std::min(1.0f, 0.3f + 0.7f * std::log10(e)), 0.0f, 0.0f};
    heatmap.beauty[p] = glm::vec4(colour, 1.0f);
  }
  writePng(path, heatmap);
}

std::string describe(const ParityReport& report) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%dx%d: %zu pixels covered on both, %zu silhouette pixels\n", report.width,
                report.height, report.covered, report.silhouettePixels);
  out += line;
  std::snprintf(line, sizeof line, "coverage: %zu pixels differ (%zu off silhouettes) %s\n", report.coverageMismatches,
                report.coverageMismatchesInterior, report.coveragePass ? "ok" : "FAIL");
  out += line;
  std::snprintf(line, sizeof line, "%-17s %11s %11s %11s %11s %9s %9s %9s  %s\n", "AOV", "max abs", "mean abs",
                "max rel", "mean rel", "tol", "over sil", "over int", "relative is");
  out += line;
  for (const AovParity& a : report.aovs) {
    std::snprintf(line, sizeof line, "%-17s %11.3e %11.3e %11.3e %11.3e %9.1e %9zu %9zu  %s%s\n", a.name.c_str(),
                  a.maxAbsolute, a.meanAbsolute, a.maxRelative, a.meanRelative, a.tolerance, a.overSilhouette,
                  a.overInterior, a.unit.c_str(),
                  a.tolerance <= 0 ? ""
                  : a.pass         ? " ok"
                                   : " FAIL");
    out += line;
  }
  out += report.pass ? "parity: within tolerance\n" : "parity: OUT OF TOLERANCE\n";
  return out;
}

}  // namespace facet::analysis

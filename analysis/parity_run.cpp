#include "analysis/parity_run.h"

#include <cmath>
#include <stdexcept>

#include "analysis/parity_statistics.h"
#include "analysis/reference_cache.h"
#include "engine/image_memory.h"
#include "engine/render_record.h"
#include "scenes/light_transport.h"

namespace facet::analysis {
namespace {

constexpr const char* kToleranceRule =
    "expected AOV=ABS,REL with AOV one of depth, normal, beauty and ABS, REL finite numbers >= 0";

double nonNegative(const std::string& text, const std::string& option, const std::string& override) {
  std::size_t end = 0;
  double value = NAN;
  try {
    value = std::stod(text, &end);
  } catch (const std::exception&) {
  }
  if (end != text.size() || !std::isfinite(value) || value < 0)
    throw std::invalid_argument(option + " '" + override + "': " + kToleranceRule);
  return value;
}

nlohmann::json aovJson(const AovParity& a) {
  nlohmann::json worst = nlohmann::json::array();
  for (const WorstPixel& w : a.worst)
    worst.push_back(
        {{"x", w.x}, {"y", w.y}, {"reference", w.reference}, {"candidate", w.candidate}, {"error", w.error}});
  nlohmann::json out = {{"name", a.name},
                        {"relative", a.unit},
                        {"gated", a.gated},
                        {"maxAbsolute", a.maxAbsolute},
                        {"meanAbsolute", a.meanAbsolute},
                        {"maxRelative", a.maxRelative},
                        {"meanRelative", a.meanRelative},
                        {"worstPixels", worst}};
  if (!a.gated) return out;  // no tolerance, no verdict: nothing was judged
  out["test"] = a.test;
  out["tolerance"] = {{"absolute", a.tolerance.absolute},
                      {"relative", a.tolerance.relative},
                      {"passShare", a.tolerance.passShare},
                      {"pixels", a.tolerance.interiorOnly ? "interior" : "covered"},
                      {"rule", passRule(a)}};
  if (a.test != "tolerance")
    out["tTest"] = {
        {"renders", a.renders}, {"significance", a.significance}, {"alpha", a.alpha}, {"minPValue", a.minPValue}};
  out["judged"] = a.judged;
  out["overSilhouette"] = a.overSilhouette;
  out["overInterior"] = a.overInterior;
  out["allowed"] = a.allowed;
  out["shareOver"] = a.shareOver;
  out["pass"] = a.pass;
  return out;
}

nlohmann::json reportJson(const ParityReport& r) {
  nlohmann::json aovs = nlohmann::json::array();
  for (const AovParity& a : r.aovs) aovs.push_back(aovJson(a));
  return {{"verdict", toString(r.verdict)},
          {"pass", r.pass},
          {"width", r.width},
          {"height", r.height},
          {"pixels", r.pixels},
          {"coveredOnBoth", r.covered},
          {"minCoverage", r.minCoverage},
          {"silhouettePixels", r.silhouettePixels},
          {"coverage",
           {{"mismatches", r.coverageMismatches},
            {"mismatchesOffSilhouette", r.coverageMismatchesInterior},
            {"allowed", r.coverageAllowed},
            {"pass", r.coveragePass}}},
          {"aovs", aovs}};
}

}  // namespace

ParityCase judgeParity(const std::string& name, scene::Scene scene, const std::vector<ParityCandidate>& candidates,
                       Renderer& reference, int renders, const ParityTolerances& tolerances,
                       const std::string& sizeField, const ReferenceStore& store) {
  const bool statistical = scene::estimateSeed(scene) && renders > 1;
  const int count = statistical ? renders : 1;
  // The reference's render; per candidate its render, the first pair, the
  // pairs' sums (about an image and a half) and the two mean images.
  const int working = 1 + 6 * int(candidates.size());
  // What the store keeps besides: a render, and each later render's beauty,
  // a fifth of one. The cache never refuses a scene: where that does not
  // fit, nothing is stored.
  const std::string key = rendersKey(store.key, count);
  const bool storing = !key.empty() &&
                       referenceBytes(scene.render.width, scene.render.height, count) <= kReferenceCacheBytes &&
                       imagesFitInMemory(scene, working + 1 + (count + 3) / 5);
  checkImagesFitInMemory(scene, working, sizeField);
  const std::uint32_t firstSeed = scene.environment ? scene.environment->seed : 0u;

  ParityCase out;
  out.scene = name;
  out.settings = {{"digest", settingsDigest(scene, "parity")},
                  {"text", renderSettingsText(scene, "parity")},
                  {"rendersPerBackend", count},
                  {"seeds", statistical ? nlohmann::json::array({firstSeed, firstSeed + std::uint32_t(count - 1)})
                                        : nlohmann::json::array({firstSeed})}};
  const std::optional<CachedReference> stored =
      storing && !store.fresh ? loadReference(key, scene.render.width, scene.render.height, count) : std::nullopt;
  CachedReference made;
  if (stored) {
    out.reference = stored->device;
    out.referenceCached = true;
  }
  std::vector<PairedRenders> pairs(candidates.size());
  for (const ParityCandidate& c : candidates) out.runs.push_back({c.adapter, c.adapterInfo, 0, {}});
  // Render i of every backend draws the same random numbers (seed i), so
  // that their difference is the backends' and not the estimators' noise.
  // The GPU first: it refuses what it cannot render (a scene beyond float's
  // range) before the CPU spends a render on it.
  for (int i = 0; i < count; ++i) {
    if (scene.environment) scene.environment->seed = firstSeed + std::uint32_t(i);
    std::vector<Image> gpuImages;
    for (std::size_t a = 0; a < candidates.size(); ++a) {
      RenderReport gpu = candidates[a].renderer->render(scene, Backend::Gpu);
      out.runs[a].milliseconds += gpu.totalMilliseconds();
      out.runs[a].adapterInfo["device"] = gpu.device;
      gpuImages.push_back(std::move(gpu.image));
    }
    Image cpuImage;
    if (stored) {
      cpuImage = stored->render(i);
    } else {
      RenderReport cpu = reference.render(scene, Backend::Cpu);
      out.reference = made.device = cpu.device;
      out.referenceMilliseconds += cpu.totalMilliseconds();
      cpuImage = std::move(cpu.image);
      if (storing) made.add(cpuImage);
    }
    for (std::size_t a = 0; a < candidates.size(); ++a) pairs[a].add(cpuImage, gpuImages[a]);
  }
  if (storing && !stored) storeReference(key, made);
  for (std::size_t a = 0; a < candidates.size(); ++a)
    out.runs[a].report = compareImages(pairs[a].referenceMean(), pairs[a].candidateMean(), tolerances,
                                       statistical ? &pairs[a] : nullptr);
  return out;
}

ParityTolerances parityTolerances(const std::vector<std::string>& overrides, std::size_t minCoverage,
                                  const std::string& option) {
  ParityTolerances t;
  t.minCoverage = minCoverage;
  for (const std::string& text : overrides) {
    const std::size_t equals = text.find('='), comma = text.find(',', equals == std::string::npos ? 0 : equals);
    if (equals == std::string::npos || comma == std::string::npos)
      throw std::invalid_argument(option + " '" + text + "': " + kToleranceRule);
    const std::string aov = text.substr(0, equals);
    const double absolute = nonNegative(text.substr(equals + 1, comma - equals - 1), option, text);
    const double relative = nonNegative(text.substr(comma + 1), option, text);
    Tolerance* tolerance = aov == "depth"    ? &t.depth
                           : aov == "normal" ? &t.normal
                           : aov == "beauty" ? &t.beauty
                                             : nullptr;
    if (!tolerance) throw std::invalid_argument(option + " '" + text + "': " + kToleranceRule);
    // Beauty's default absolute part is derived from the image; a given one is in radiance units.
    (aov == "beauty" ? t.beautyAbsolute.emplace() : tolerance->absolute) = absolute;
    tolerance->relative = relative;
  }
  return t;
}

std::string runName(const ParityCase& c, const ParityRun& run) { return c.scene + c.joiner + run.adapter; }

nlohmann::json parityCaseJson(const ParityCase& c) {
  nlohmann::json runs = nlohmann::json::array();
  for (const ParityRun& run : c.runs) {
    nlohmann::json entry = reportJson(run.report);
    entry["name"] = runName(c, run);
    if (!run.adapterInfo.empty()) {
      entry["adapter"] = run.adapterInfo;
      entry["adapter"]["name"] = run.adapter;
    }
    entry["milliseconds"] = run.milliseconds;
    runs.push_back(entry);
  }
  nlohmann::json scene = {
      {"scene", c.scene},
      {"reference", {{"name", c.reference}, {"milliseconds", c.referenceMilliseconds}, {"cached", c.referenceCached}}},
      {"settings", c.settings},
      {"runs", runs}};
  if (!c.error.empty()) scene["error"] = c.error;
  return scene;
}

}  // namespace facet::analysis

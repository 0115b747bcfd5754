// What `facet render` says of each render: the summary for people, and the
// JSON of --json (README.md, "Rendering on a farm").
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "engine/adaptive_render.h"
#include "engine/renderer.h"
#include "scenes/scene.h"

namespace facet::cli {

// One image to render: its frame (none for a still) and where it goes.
struct RenderJob {
  std::optional<int> frame;
  std::string exr;  // empty: none
  std::string png;  // empty: none
  std::optional<std::uint32_t> seed;  // --seeds: the render's random numbers
};

// "default studio environment" for a scene that got it
// (scenes/studio_environment.h), else "scene".
std::string lightingName(const scene::Scene& scene);

// How the pixels were sampled: "16 spp", or for adaptive rounds (`adaptive`
// not null) their samples, the noise left and why they stopped; and why,
// where facet chose.
std::string describeSampling(const RenderReport& report, const AdaptiveReport* adaptive);

// One line per render (the default): outputs, size, sampling and noise,
// method, device, time and rate, and whatever facet added or left out.
void printSummaryLine(const scene::Scene& scene, const RenderReport& report, const AdaptiveReport* adaptive,
                      const RenderJob& job, double wallMilliseconds);
// --verbose: the per-object statistics, the lighting, every stage's time
// and the rays per bounce.
void printSummary(const scene::Scene& scene, const RenderReport& report, const AdaptiveReport* adaptive,
                  const RenderJob& job, double wallMilliseconds);

// Adaptive rounds in --json, alike for facet render and facet preview:
// rounds, samples, the spread of samples per pixel, the largest tile error,
// the threshold and why they stopped.
nlohmann::json adaptiveJson(const AdaptiveReport& adaptive);

// Every stage's milliseconds by the stage's name, as --json's "stages_ms".
nlohmann::json stagesJson(const RenderReport& report);

// One entry of --json's "renders".
nlohmann::json renderJson(const RenderReport& report, const AdaptiveReport* adaptive, const RenderJob& job,
                          double wallMilliseconds);

std::uint64_t peakResidentBytes();

}  // namespace facet::cli

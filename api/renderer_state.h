// What a public Renderer holds, shared by the API's files that render.
#pragma once

#include <mutex>
#include <string>

#include "engine/adaptive_render.h"
#include "engine/renderer.h"
#include "facet/render.h"

namespace facet::v0 {

struct Renderer::State {
  explicit State(const std::string& adapter) : engine(adapter) {}
  // The engine's renderer holds one GPU context and its buffers: one render at a time.
  std::mutex rendering;
  facet::Renderer engine;
};

}  // namespace facet::v0

namespace facet::api {

// What `facet render --json` says of the sampling (`spp`, `adaptive`, `sampling`).
v0::SamplingReport samplingReport(const RenderReport& report, const AdaptiveReport& rounds);
// Adaptive rounds alone, as the preview stage takes them.
v0::SamplingReport adaptiveSampling(const AdaptiveReport& rounds);

}  // namespace facet::api

// Rendering a Scene on the GPU kernels (Vulkan compute; lavapipe when there is
// no GPU) or on the scalar double-precision CPU reference.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/error.h"
#include "facet/image.h"
#include "facet/scene.h"

namespace facet {
namespace v0 {

enum class Backend { Gpu, Cpu };
enum class Method { Exact, Tessellated };

// Unset fields keep the scene's own choice.
struct RenderSettings {
  Backend backend = Backend::Gpu;
  std::optional<int> width, height;
  std::optional<Method> method;
  std::optional<int> spp;        // one pass of a square number; none: the scene file's, or chosen (docs/api.md)
  std::optional<int> tessLevel;  // tessellated method
  // Continuations of each camera sample's path, in [0, 64]; 0 is direct light
  // only. Above 0: an environment, if any, sampled or filtered with
  // occlusion on (docs/rendering.md, "Paths"). None: the scene's, or where
  // it states none, chosen from the scene (docs/rendering.md, "Light
  // transport chosen by the scene").
  std::optional<int> bounces;
};

// The rays of one bounce of the paths: bounce 0 casts the camera rays.
struct BounceRays {
  std::uint64_t rays = 0;  // camera or continuation rays
  std::uint64_t hits = 0;  // of those, the ones that hit a surface
  std::uint64_t shadowRays = 0;
};

// The camera samples a render took (docs/rendering.md, "Converged by
// default"): one pass, or adaptive rounds and the noise they left.
struct SamplingReport {
  int spp = 0;  // one pass of this many; 0: adaptive rounds
  // Adaptive rounds: how many ran, the samples per pixel they left over the
  // image (mean, fewest, most), the largest tile's relative standard error
  // against the threshold, and what stopped them: "converged", "sample cap"
  // or "time limit".
  int rounds = 0;
  double sppMean = 0;
  int sppMin = 0, sppMax = 0;
  double maxTileError = 0, noiseThreshold = 0;
  std::string stop;
  // Where facet chose the sampling, why; empty where it was stated.
  std::string why;
};

struct RenderResult {
  Image image;
  std::string device;  // what ran it
  double milliseconds = 0;
  int bounces = 0;  // as rendered, stated or chosen
  // What light transport was chosen and why; empty where the scene and the
  // settings stated it.
  std::string lightTransport;
  std::vector<BounceRays> raysPerBounce;  // bounce 0 to the last; empty unless bounces > 0
  SamplingReport sampling;
};

struct AovParity {
  std::string name;
  bool gated = false;
  std::string test;  // gated: "tolerance" or "paired t-test"
  std::string rule;  // gated: the pass rule in words, with its numbers
  double maxRelative = 0, meanRelative = 0;
  double tolerance = 0;               // its relative part, or the absolute one where there is none; 0: not gated
  double shareOver = 0;               // of the judged pixels
  std::size_t over = 0, allowed = 0;  // gated: judged pixels over tolerance, and how many the rule allows
  double minPValue = 1;               // the paired t-test's smallest p-value
  bool pass = true;
};

// `facet parity`'s options (docs/parity.md), under its rules.
struct ParityOptions {
  // A Monte Carlo beauty's (sampled or filtered lighting, paths) renders per
  // backend, seeds apart, judged by the paired t-test; 1: one render each,
  // judged by tolerance alone. In [1, 1024].
  int renders = 16;
  std::vector<std::string> tolerances;  // "AOV=ABS,REL" as --tolerance (AOV: depth, normal, beauty)
  std::size_t minCoverage = 16;         // pixels covered on both below which nothing is judged
};

// GPU against the CPU reference, AOV by AOV (docs/parity.md), as `facet
// parity` judges it: one implementation.
struct ParityReport {
  int width = 0, height = 0;
  std::size_t covered = 0;  // on both images
  std::size_t coverageMismatches = 0;
  bool coveragePass = true;
  std::vector<AovParity> aovs;
  std::string verdict;  // "pass", "fail" or "insufficient coverage"
  bool pass = true;     // verdict "pass"
  int renders = 1;      // per backend
  std::string summary;  // the table `facet parity` prints
  std::string json;     // the scene's entry of `facet parity --json`
};

struct PreviewSettings;
struct PreviewSheet;
struct WatchSettings;
struct WatchPass;

// Keeps the GPU device and its compiled kernels between renders. Safe to
// share between threads: its renders run one at a time. `adapter`: a substring of the adapter's name (default:
// $FACET_ADAPTER, else the first hardware GPU, else lavapipe).
class Renderer {
 public:
  explicit Renderer(const std::string& adapter = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  RenderResult render(const Scene& scene, const RenderSettings& settings = {});
  // Renders on both backends (settings.backend is ignored).
  ParityReport parity(const Scene& scene, const RenderSettings& settings = {}, const ParityOptions& options = {});

  // The preview stage (<facet/preview.h>): frame `frame` (0 without a
  // turntable) of each material on `model`. writePreview writes every frame
  // as `facet preview` does: the sheet to `output` (.png), or with a
  // turntable the movie (.mp4 or .gif) by the ffmpeg found on PATH, whose
  // frames are the picture alone for one material; the output is checked,
  // and ffmpeg found, before the first render.
  PreviewSheet preview(const Scene& model, const PreviewSettings& settings, int frame = 0);
  void writePreview(const Scene& model, const PreviewSettings& settings, const std::string& output, double fps = 24);

  // Watches the scene file `scene` (<facet/watch.h>): onPass after each
  // pass of each picture, returning whether to go on. A later load or
  // render refused on bad input goes to onBadInput, which returns whether
  // to go on: the watch keeps the last picture and waits for the next
  // change; without onBadInput it ends the watch, thrown. The first
  // picture's errors are thrown.
  void watch(const std::string& scene, const std::function<bool(const WatchPass&)>& onPass,
             const WatchSettings& settings, const std::function<bool(const Error&)>& onBadInput = {});

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The library's version, "major.minor.patch".
const char* version();

}  // namespace v0
#ifndef FACET_IMPLEMENTATION  // inside libfacet, facet:: is also the engine's
using namespace v0;
#endif
}  // namespace facet

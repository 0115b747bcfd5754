// A parity run (docs/parity.md): a scene rendered by each candidate GPU and
// by the CPU reference, several times seeds apart where its beauty is a
// Monte Carlo estimate, and judged AOV by AOV (parity.h), with the JSON
// `facet parity --json` writes of it. The command line and the APIs judge
// by this one implementation.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "analysis/parity.h"
#include "engine/renderer.h"
#include "scenes/scene.h"

namespace facet::analysis {

// One candidate judged against the reference: a GPU adapter's renders
// against the CPU's, or one stored image against another.
struct ParityRun {
  std::string adapter;                                    // the adapter's name, or the candidate file
  nlohmann::json adapterInfo = nlohmann::json::object();  // driver, its version, API version
  double milliseconds = 0;                                // the candidate's renders, all of them
  ParityReport report;
};

struct ParityCase {
  std::string scene;            // the scene file, or the candidate image
  std::string reference;        // what rendered the reference: the CPU's device, or the reference image
  std::string joiner = " on ";  // between the scene and a run's adapter in a run's name
  double referenceMilliseconds = 0;
  bool referenceCached = false;  // the reference's renders came from the cache (reference_cache.h)
  nlohmann::json settings = nlohmann::json::object();  // digest, text and renders per backend
  std::vector<ParityRun> runs;
  // What stopped the scene before it was judged (facet's message: a file
  // that does not load, a device lost); it then has no runs.
  std::string error;
};

// A GPU to judge: the Renderer on its adapter, the adapter's name and its
// driver's description.
struct ParityCandidate {
  Renderer* renderer = nullptr;
  std::string adapter;
  nlohmann::json adapterInfo = nlohmann::json::object();
};

// Where the CPU reference's renders are kept between runs
// (reference_cache.h): nowhere without a key (referenceKey's); `fresh`
// renders them anew and replaces what is stored.
struct ReferenceStore {
  std::string key;
  bool fresh = false;
};

// `scene`, with nothing left to choose (scenes/light_transport.h), judged
// on every candidate against the CPU reference that `reference` renders.
// Where its beauty is a Monte Carlo estimate (sampled or filtered lighting,
// paths), each backend renders it `renders` times with seeds 0..renders-1
// apart and beauty is judged by the paired t-test. `sizeField` names the
// image size in the error of an image that does not fit in memory. The
// reference's renders come from `store` where it holds them, and go there
// where it does not.
ParityCase judgeParity(const std::string& name, scene::Scene scene, const std::vector<ParityCandidate>& candidates,
                       Renderer& reference, int renders, const ParityTolerances& tolerances,
                       const std::string& sizeField, const ReferenceStore& store = {});

// The tolerances with `overrides` ("AOV=ABS,REL", AOV one of depth, normal,
// beauty) and the coverage a verdict needs; throws std::invalid_argument
// "<option> '<text>': <rule>" for a malformed override.
ParityTolerances parityTolerances(const std::vector<std::string>& overrides, std::size_t minCoverage,
                                  const std::string& option);

// "<scene> on <adapter>", or "<candidate> against <reference>": a JUnit
// suite's name and how an error line names a run.
std::string runName(const ParityCase& c, const ParityRun& run);

// One scene of `facet parity --json`: its settings, the reference, and each
// run's verdict, coverage and AOVs.
nlohmann::json parityCaseJson(const ParityCase& c);

}  // namespace facet::analysis

// What `facet parity` and `facet compare` hand to people and to CI: the
// JSON of --json and the JUnit XML of --junit (docs/parity.md), one test case
// per scene x adapter x AOV.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "analysis/parity.h"

namespace facet::cli {

// "<scene> on <adapter>", or "<candidate> against <reference>": a JUnit
// suite's name and how an error line names a run.
struct ParityCase;
struct ParityRun;
std::string runName(const ParityCase& c, const ParityRun& run);

// One candidate judged against the reference: a GPU adapter's renders
// against the CPU's, or one stored image against another.
struct ParityRun {
  std::string adapter;                                    // the adapter's name, or the candidate file
  nlohmann::json adapterInfo = nlohmann::json::object();  // driver, its version, API version
  double milliseconds = 0;                                // the candidate's renders, all of them
  analysis::ParityReport report;
};

struct ParityCase {
  std::string scene;            // the scene file, or the candidate image
  std::string reference;        // what rendered the reference: the CPU's device, or the reference image
  std::string joiner = " on ";  // between the scene and a run's adapter in a run's name
  double referenceMilliseconds = 0;
  nlohmann::json settings = nlohmann::json::object();  // digest, text and renders per backend
  std::vector<ParityRun> runs;
  // What stopped the scene before it was judged (facet's message: a file
  // that does not load, a device lost); it then has no runs.
  std::string error;
};

// `passRule`'s numbers as JSON, and the whole run with the facet version.
nlohmann::json parityJson(const std::vector<ParityCase>& cases);

// A JUnit XML document: a <testsuite> per scene and adapter, a <testcase>
// per AOV and one for coverage; AOVs reported but not gated are <skipped>.
// A scene that errored is a suite of one <testcase name="render"> holding
// an <error> with its message.
std::string junitXml(const std::vector<ParityCase>& cases);

// "runs failed: a.json on llvmpipe (out of tolerance), ..." for the error
// line, or "" when every run passed.
std::string failedRuns(const std::vector<ParityCase>& cases);

}  // namespace facet::cli

// What `facet parity` and `facet compare` hand to people and to CI: the
// JSON of --json and the JUnit XML of --junit (docs/parity.md), one test case
// per scene x adapter x AOV.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "analysis/parity_run.h"

namespace facet::cli {

using analysis::ParityCase;
using analysis::ParityRun;
using analysis::runName;

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

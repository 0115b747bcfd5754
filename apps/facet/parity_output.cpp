#include "parity_output.h"

#include <cstdio>

#include "facet/version.h"

namespace facet::cli {
namespace {

using analysis::AovParity;
using analysis::ParityReport;
using analysis::Verdict;

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // XML 1.0 allows no other control characters.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t') out += c;
    }
  }
  return out;
}

std::string format(const char* pattern, auto... values) {
  char text[1024];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

// The coverage test case and one per AOV: "" when it passed, else the failure.
struct JunitCase {
  std::string name, failure, skipped, details;
};

std::vector<JunitCase> junitCases(const ParityReport& r) {
  std::vector<JunitCase> cases;
  const std::string coverage = format(
      "%zu pixels covered on both (%zu needed); %zu differ, %zu off silhouettes (at "
      "most %zu allowed, none off silhouettes)",
      r.covered, r.minCoverage, r.coverageMismatches, r.coverageMismatchesInterior, r.coverageAllowed);
  if (r.verdict == Verdict::InsufficientCoverage)
    cases.push_back({"coverage", "insufficient coverage: " + coverage, "", coverage});
  else
    cases.push_back({"coverage", r.coveragePass ? "" : "coverage differs: " + coverage, "", coverage});
  for (const AovParity& a : r.aovs) {
    const std::string errors = format("max abs %.3e, mean abs %.3e, max rel %.3e, mean rel %.3e (relative is %s)",
                                      a.maxAbsolute, a.meanAbsolute, a.maxRelative, a.meanRelative, a.unit.c_str());
    if (!a.gated) {
      cases.push_back({a.name, "", "reported, not gated", errors});
      continue;
    }
    std::string details = analysis::passRule(a) + "; " + errors;
    if (!a.worst.empty() && a.worst.front().error > 0)
      details +=
          format("; worst at (%d, %d): %.3g x tolerance", a.worst.front().x, a.worst.front().y, a.worst.front().error);
    if (r.verdict == Verdict::InsufficientCoverage)
      cases.push_back({a.name, "", "insufficient coverage: nothing to judge", details});
    else
      cases.push_back({a.name,
                       a.pass ? ""
                              : format("%zu of %zu pixels over, %zu allowed: %s", a.over(), a.judged, a.allowed,
                                       analysis::passRule(a).c_str()),
                       "", details});
  }
  return cases;
}

}  // namespace

nlohmann::json parityJson(const std::vector<ParityCase>& cases) {
  nlohmann::json scenes = nlohmann::json::array();
  bool pass = true;
  for (const ParityCase& c : cases) {
    scenes.push_back(analysis::parityCaseJson(c));
    pass = pass && c.error.empty();
    for (const ParityRun& run : c.runs) pass = pass && run.report.pass;
  }
  return {{"facetVersion", FACET_VERSION_STRING}, {"pass", pass}, {"scenes", scenes}};
}

std::string junitXml(const std::vector<ParityCase>& cases) {
  std::string suites;
  std::size_t tests = 0, failures = 0, errors = 0, skipped = 0;
  for (const ParityCase& c : cases) {
    if (!c.error.empty()) {
      const std::string name = escaped(c.scene);
      suites += "  <testsuite name=\"" + name + "\" tests=\"1\" failures=\"0\" errors=\"1\" skipped=\"0\">\n" +
                "    <testcase classname=\"" + name + "\" name=\"render\">\n      <error message=\"" +
                escaped(c.error) + "\" type=\"error\"/>\n    </testcase>\n  </testsuite>\n";
      ++tests;
      ++errors;
    }
    for (const ParityRun& run : c.runs) {
      const std::vector<JunitCase> judged = junitCases(run.report);
      std::size_t suiteFailures = 0, suiteSkipped = 0;
      std::string body;
      const std::string classname = escaped(runName(c, run));
      for (const JunitCase& j : judged) {
        body += "    <testcase classname=\"" + classname + "\" name=\"" + escaped(j.name) + "\"";
        if (j.failure.empty() && j.skipped.empty()) {
          body += ">\n      <system-out>" + escaped(j.details) + "</system-out>\n    </testcase>\n";
          continue;
        }
        body += ">\n";
        if (!j.failure.empty()) {
          ++suiteFailures;
          body += "      <failure message=\"" + escaped(j.failure) + "\" type=\"" +
                  escaped(analysis::toString(run.report.verdict)) + "\">" + escaped(j.details) + "</failure>\n";
        } else {
          ++suiteSkipped;
          body += "      <skipped message=\"" + escaped(j.skipped) + "\"/>\n";
        }
        body += "      <system-out>" + escaped(j.details) + "</system-out>\n    </testcase>\n";
      }
      suites += format(
                    "  <testsuite name=\"%s\" tests=\"%zu\" failures=\"%zu\" errors=\"0\" skipped=\"%zu\" "
                    "time=\"%.3f\">\n",
                    classname.c_str(), judged.size(), suiteFailures, suiteSkipped,
                    (c.referenceMilliseconds + run.milliseconds) / 1000) +
                body + "  </testsuite>\n";
      tests += judged.size();
      failures += suiteFailures;
      skipped += suiteSkipped;
    }
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" +
         format("<testsuites name=\"facet parity %s\" tests=\"%zu\" failures=\"%zu\" errors=\"%zu\" skipped=\"%zu\">\n",
                FACET_VERSION_STRING, tests, failures, errors, skipped) +
         suites + "</testsuites>\n";
}

std::string failedRuns(const std::vector<ParityCase>& cases) {
  std::string out;
  for (const ParityCase& c : cases)
    for (const ParityRun& run : c.runs)
      if (!run.report.pass)
        out += (out.empty() ? "" : ", ") + runName(c, run) + " (" +
               (run.report.verdict == Verdict::Fail ? "out of tolerance" : analysis::toString(run.report.verdict)) +
               ")";
  return out;
}

}  // namespace facet::cli

#include "parity_options.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/parity_heatmap.h"
#include "engine/image/image_io.h"
#include "exit_codes.h"

namespace facet::cli {

void addParityFlags(CLI::App& command, ParityFlags& flags) {
  command
      .add_option("--tolerance", flags.tolerances,
                  "A gated AOV's tolerance, |d| <= ABS + REL |reference|: AOV=ABS,REL with AOV depth, normal "
                  "(radians) or beauty; repeatable")
      ->take_all();
  command
      .add_option("--min-coverage", flags.minCoverage,
                  "Pixels covered on both images below which nothing is judged (verdict: insufficient coverage)")
      ->capture_default_str();
  command.add_option("--heatmap", flags.heatmap,
                     "Write the per-pixel error (in units of tolerance) as a PNG with a legend");
  command.add_option("--heatmap-aov", flags.heatmapAov, "The heat map of one gated AOV (default: the largest of them)")
      ->check(CLI::IsMember({"depth", "shading normal", "beauty"}));
  command.add_option("--junit", flags.junit, "Write a JUnit XML report: a test case per scene, adapter and AOV");
  command.add_flag("--json", flags.json, "Machine-readable report");
}

analysis::ParityTolerances chosenTolerances(const ParityFlags& flags) {
  return analysis::parityTolerances(flags.tolerances, flags.minCoverage, "--tolerance");
}

void checkParityOutputs(const ParityFlags& flags, std::size_t runs) {
  if (!flags.heatmap.empty()) {
    checkOutputPath("--heatmap", flags.heatmap);
    checkOutputExtension("--heatmap", flags.heatmap, ".png");
    if (runs != 1)
      throw std::invalid_argument("--heatmap '" + flags.heatmap + "': draws one run, and there are " +
                                  std::to_string(runs) + " (scenes x adapters)");
  }
  if (!flags.heatmapAov.empty() && flags.heatmap.empty())
    throw std::invalid_argument("--heatmap-aov '" + flags.heatmapAov + "': needs --heatmap");
  if (!flags.junit.empty()) checkOutputPath("--junit", flags.junit);
  if (!flags.junit.empty() && !flags.heatmap.empty() && namesSameFile(flags.junit, flags.heatmap))
    throw OutputError("--junit '" + flags.junit + "': names the same file as --heatmap");
}

void reportParity(const ParityFlags& flags, const std::vector<ParityCase>& cases, const std::string& command) {
  std::vector<OutputFile> outputs;
  const std::string junit = flags.junit.empty() ? std::string() : junitXml(cases);
  if (!flags.junit.empty())
    outputs.push_back({flags.junit, [&](const std::filesystem::path& path) {
                         writeBytes(path, std::vector<std::uint8_t>(junit.begin(), junit.end()), flags.junit);
                       }});
  // One run, checked before any render; none where its scene errored.
  if (!flags.heatmap.empty() && !cases.front().runs.empty()) {
    const analysis::ParityReport& report = cases.front().runs.front().report;
    outputs.push_back(analysis::heatmapFile(flags.heatmap, report, flags.heatmapAov));
  }
  writeAllOrNothing(outputs);
  if (flags.json) {
    std::printf("%s\n", parityJson(cases).dump(2).c_str());
  } else {
    for (const ParityCase& c : cases) {
      if (!c.error.empty()) std::printf("%s: error: %s\n", c.scene.c_str(), c.error.c_str());
      // The line a CI log needs to tell two runs' settings apart.
      if (c.settings.contains("text"))
        std::printf("%s: settings %s, %d render(s) per backend (digest %s)\n", c.scene.c_str(),
                    c.settings["text"].get<std::string>().c_str(), c.settings["rendersPerBackend"].get<int>(),
                    c.settings.value("digest", c.settings.value("pictureDigest", "")).c_str());
      for (const ParityRun& run : c.runs)
        std::printf("%s (reference: %s%s)\n%s", runName(c, run).c_str(), c.reference.c_str(),
                    c.referenceCached ? ", from the cache" : "", analysis::describe(run.report).c_str());
    }
    for (const OutputFile& output : outputs) std::printf("wrote %s\n", output.path.c_str());
  }
  const std::string failed = failedRuns(cases);
  if (failed.empty()) return;
  std::size_t runs = 0;
  for (const ParityCase& c : cases) runs += c.runs.size();
  if (runs == 1) {
    const ParityCase& c = cases.front();
    const analysis::ParityReport& r = c.runs.front().report;
    if (r.verdict == analysis::Verdict::InsufficientCoverage)
      throw CheckFailed(command + ": " + c.scene + ": insufficient coverage: " + std::to_string(r.covered) +
                        " pixels covered on both, fewer than the " +
                        std::to_string(std::max<std::size_t>(r.minCoverage, 1)) + " needed to judge (--min-coverage)");
    throw CheckFailed(command + ": " + c.scene + " is out of tolerance");
  }
  throw CheckFailed(command + ": runs that did not pass: " + failed);
}

}  // namespace facet::cli

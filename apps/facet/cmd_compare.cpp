// facet compare: judge stored renders against stored references (golden
// images) by parity's rules (analysis/stored_parity.h, docs/parity.md);
// exits with kCheckFailed when they do not pass and kNotComparable when the
// two sets estimate different pictures. Every EXR needs the ids layer, which
// says which pixels are covered.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/stored_parity.h"
#include "commands.h"
#include "parity_options.h"
#include "parity_output.h"
#include "scene_warnings.h"

namespace facet::cli {
namespace {

struct CompareOptions {
  std::vector<std::string> files;  // the references, then as many candidates
  ParityFlags flags;
};

void runCompare(const CompareOptions& o) {
  const analysis::ParityTolerances tolerances = chosenTolerances(o.flags);
  checkParityOutputs(o.flags, 1);
  if (o.files.size() % 2 != 0)
    throw std::invalid_argument("compare: " + std::to_string(o.files.size()) +
                                " files: give the references, then as many candidates");
  const std::size_t k = o.files.size() / 2;
  const std::vector<std::filesystem::path> references(o.files.begin(), o.files.begin() + std::ptrdiff_t(k)),
      candidates(o.files.begin() + std::ptrdiff_t(k), o.files.end());
  analysis::StoredJudgement stored;
  try {
    stored = analysis::judgeStoredRenders(references, candidates, tolerances);
  } catch (const analysis::NotComparable& e) {
    // No verdict on the candidate, but the reports say why there is none.
    ParityCase notJudged;
    notJudged.scene = o.files[k];
    notJudged.reference = o.files.front();
    notJudged.joiner = " against ";
    notJudged.error = e.what();
    reportParity(o.flags, {notJudged}, "compare");
    throw analysis::NotComparable("compare: " + o.files[k] + ": " + e.what());
  }
  printWarnings(stored.warnings, false);
  reportParity(o.flags, {stored.judged}, "compare");
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* c =
      app.add_subcommand("compare", "Judge stored renders against stored references (golden images) by parity's rules");
  c->add_option("files", o->files,
                "The reference EXRs (golden images, rendered with the ids layer: render --aovs all), then as many "
                "candidate EXRs judged against them, paired by seed")
      ->required()
      ->check(CLI::ExistingFile);
  addParityFlags(*c, o->flags);
  c->callback([o] { runCompare(*o); });
}

}  // namespace facet::cli

// facet compare: judge a stored render against a stored reference (a golden
// image) by parity's rules (analysis/parity.h, docs/parity.md); exits with
// kCheckFailed when it does not pass. Both EXRs need the ids layer, which
// says which pixels are covered.
#include <CLI/CLI.hpp>

#include <memory>
#include <stdexcept>
#include <string>

#include "analysis/parity.h"
#include "commands.h"
#include "engine/image/exr_file.h"
#include "parity_options.h"
#include "parity_output.h"

namespace facet::cli {
namespace {

struct CompareOptions {
  std::string reference;
  std::string candidate;
  ParityFlags flags;
};

// An unreadable file is bad input, not an internal error.
Image readInput(const std::string& path) {
  try {
    return readExr(path);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

void runCompare(const CompareOptions& o) {
  const analysis::ParityTolerances tolerances = chosenTolerances(o.flags);
  checkParityOutputs(o.flags, 1);
  const Image reference = readInput(o.reference), candidate = readInput(o.candidate);
  if (reference.width != candidate.width || reference.height != candidate.height)
    throw std::invalid_argument(o.candidate + ": " + std::to_string(candidate.width) + "x" +
                                std::to_string(candidate.height) + " pixels, and " + o.reference + " has " +
                                std::to_string(reference.width) + "x" + std::to_string(reference.height));
  ParityCase stored{o.candidate, o.reference, " against ", 0, nlohmann::json::object(), {}};
  stored.runs.push_back(
      {o.reference, nlohmann::json::object(), 0, analysis::compareImages(reference, candidate, tolerances)});
  reportParity(o.flags, {stored}, "compare");
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* c = app.add_subcommand("compare", "Judge a stored render against a stored reference by parity's rules");
  c->add_option("reference", o->reference, "The reference EXR (with the ids layer: render --aovs all)")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("candidate", o->candidate, "The EXR judged against it")->required()->check(CLI::ExistingFile);
  addParityFlags(*c, o->flags);
  c->callback([o] { runCompare(*o); });
}

}  // namespace facet::cli

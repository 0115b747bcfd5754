// facet compare: judge a stored render against a stored reference (a golden
// image) by parity's rules (analysis/parity.h, docs/parity.md); exits with
// kCheckFailed when it does not pass. Both EXRs need the ids layer, which
// says which pixels are covered.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdint>
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

// An unreadable file is bad input, not an internal error; so is an EXR
// without the ids layer, whose pixels would all read as missed and be
// judged "insufficient coverage" when the surface is plainly there.
Image readInput(const std::string& path) {
  Image image;
  try {
    image = readExr(path);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  const bool anyCovered =
      std::any_of(image.patchId.begin(), image.patchId.end(), [](std::uint32_t id) { return id != Image::kNoId; });
  const bool anyHit = std::any_of(image.beauty.begin(), image.beauty.end(), [](const glm::vec4& b) { return b.a > 0; });
  if (!anyCovered && anyHit)
    throw std::invalid_argument(path +
                                ": has no ids layer (patchId), which says which pixels are covered: render it with "
                                "--aovs all (or a list with ids)");
  return image;
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

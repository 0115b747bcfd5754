// The flags `facet parity` and `facet compare` share: the tolerances and the
// coverage a verdict needs, and where the verdict goes (the table, --json,
// --junit, --heatmap); docs/parity.md.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/parity.h"
#include "parity_output.h"

namespace facet::cli {

struct ParityFlags {
  std::vector<std::string> tolerances;  // AOV=ABS,REL
  std::size_t minCoverage = analysis::ParityTolerances{}.minCoverage;
  std::string heatmap;
  std::string heatmapAov;
  std::string junit;
  bool json = false;
};

void addParityFlags(CLI::App& command, ParityFlags& flags);

// Throws std::invalid_argument "--tolerance '<text>': <rule>" for a
// malformed override.
analysis::ParityTolerances chosenTolerances(const ParityFlags& flags);

// Every output path checked before the first render; --heatmap needs
// exactly one run to draw.
void checkParityOutputs(const ParityFlags& flags, std::size_t runs);

// The table (or --json) on stdout, the JUnit file and the heat map; throws
// CheckFailed "<command>: ..." naming each run that did not pass.
void reportParity(const ParityFlags& flags, const std::vector<ParityCase>& cases, const std::string& command);

}  // namespace facet::cli

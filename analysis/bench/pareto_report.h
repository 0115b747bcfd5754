// The Pareto section's report of one scenario: the points' CSV, the
// time-against-error chart with its frontier, the reference beside the
// render worth showing, and prose read off the measured points.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/bench/pareto_measure.h"

namespace facet::analysis::bench::pareto {

// Three significant digits, for prose and tables (the CSV keeps every digit).
std::string threeDigits(double value);

void reportScenario(const Scenario& s, const std::vector<Point>& points, const Image& reference,
                    const std::filesystem::path& directory, const std::string& relative, const std::string& subtitle,
                    const std::string& notes, Report& report);

}  // namespace facet::analysis::bench::pareto

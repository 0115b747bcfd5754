// What raycast_bench prints and writes: the Markdown tables of every row and
// of Embree at facet GPU's depth error, and every row as CSV.
#pragma once

#include <string>
#include <vector>

#include "benchmarks/raycast_measure.h"

namespace facet::benchmarks::raycast {

void printTables(const Measurements& run, bool quick);

void writeRowsCsv(const std::string& csvPath, const std::vector<Row>& rows);

}  // namespace facet::benchmarks::raycast

// gnuplot, run as a separate process, draws every chart of the analyses.
#pragma once

#include <filesystem>
#include <string>

namespace facet::analysis {

// Runs gnuplot on `script`, which reads `data` from the file named by the
// string variable DATA and writes the file named by OUTPUT; the terminal (SVG or PNG, `width` x
// `height`) follows the extension of `out`. The image is written next to
// `out` under a temporary name and renamed, so `out` is never half-written; a
// chart gnuplot leaves incomplete (a full disk) is an error, and no `out`.
void runGnuplot(std::string script, const std::string& data, const std::filesystem::path& out, int width = 800,
                int height = 640);

}  // namespace facet::analysis

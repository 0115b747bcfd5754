// gnuplot, run as a separate process found on PATH and under the control of
// engine/image/child_process.h, draws every chart of the analyses.
#pragma once

#include <filesystem>
#include <string>

namespace facet::analysis {

// What gnuplot may take for one chart before it is ended: far beyond the
// few thousand points of any chart here.
inline constexpr double kGnuplotTimeLimit = 120;

// Runs gnuplot on `script`, which reads `data` from the file named by the
// string variable DATA and writes the file named by OUTPUT; the terminal (SVG or PNG, `width` x
// `height`) follows the extension of `out`. The image is written next to
// `out` under a temporary name and renamed, so `out` is never half-written; a
// chart gnuplot leaves incomplete (a full disk), a gnuplot that fails or
// outlasts its time limit, or one that is missing, is an error, and no `out`.
void runGnuplot(std::string script, const std::string& data, const std::filesystem::path& out, int width = 800,
                int height = 640);

}  // namespace facet::analysis

// The heat map of a parity run as an 8-bit PNG: each pixel's error in units
// of its tolerance, black (none) through green (at tolerance) to red (10x
// over and beyond), blue where coverage differs; enlarged to be seen, with a
// legend under it that names the AOV and gives the scale.
#pragma once

#include <filesystem>
#include <string>

#include "analysis/parity.h"
#include "engine/image/image_io.h"

namespace facet::analysis {

// The heat of one gated AOV by name, or the largest over the gated AOVs when
// `aov` is empty; throws std::invalid_argument naming an AOV that is not gated.
// The PNG is drawn here and written by the OutputFile (image_io.h).
OutputFile heatmapFile(const std::filesystem::path& path, const ParityReport& report, const std::string& aov = {});

}  // namespace facet::analysis

// GPU-CPU parity: an image compared with the CPU reference's, AOV by AOV,
// under the tolerances of docs/rendering.md ("Parity"). Covered, silhouette
// and interior pixels and each error are those of analysis/image_compare.h.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/image/image.h"

namespace facet::analysis {

struct ParityTolerances {
  double coverageShare = 1e-3;
  double depthRelative = 1e-4;
  double normalRadians = 1e-3;
  double beautyRelative = 1e-3;
  double beautyShare = 0.999;  // of covered pixels within beautyRelative
};

// One AOV over the pixels covered on both images.
struct AovParity {
  std::string name;
  std::string unit;  // what "relative" means for it
  double maxAbsolute = 0;
  double meanAbsolute = 0;
  double maxRelative = 0;  // angles in radians for normals
  double meanRelative = 0;
  double tolerance = 0;            // on the relative error; 0 when the AOV is only reported
  std::size_t overSilhouette = 0;  // pixels over tolerance
  std::size_t overInterior = 0;
  double shareOver = 0;  // of the compared pixels
  bool pass = true;
};

struct ParityReport {
  int width = 0;
  int height = 0;
  std::size_t pixels = 0;
  std::size_t covered = 0;  // on both
  std::size_t silhouettePixels = 0;
  std::size_t coverageMismatches = 0;          // all of them
  std::size_t coverageMismatchesInterior = 0;  // not on a silhouette: always a failure
  bool coveragePass = true;
  std::vector<AovParity> aovs;
  bool pass = true;
  // Per pixel, the largest error over the gated AOVs in units of its
  // tolerance; -1 where coverage differs, 0 where both miss.
  std::vector<float> heat;
};

ParityReport compareImages(const Image& reference, const Image& candidate, const ParityTolerances& tolerances = {});

// The heat map as an 8-bit PNG: black (no error) through green (at
// tolerance) to red (10x over), blue where coverage differs. Atomic write.
void writeHeatmap(const std::filesystem::path& path, const ParityReport& report);

// A table for people, one AOV a line.
std::string describe(const ParityReport& report);

}  // namespace facet::analysis

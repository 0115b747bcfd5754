// The stability map's bookkeeping (bench section "stability"): what one
// render did wrong against its reference, and the CSV, heat maps, tables and
// generated prose that gather those cells per sweep.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench/bench.h"

namespace facet::analysis::bench::stability {

// Per-pixel limits beyond which a covered pixel counts as "over tolerance".
struct Tolerance {
  double depthRelative = 1e-4;
  double normalRadians = 1e-3;
  double beautyRelative = 1e-2;  // beautyRelativeError (analysis/image_compare.h)
};

// One method at one condition value.
struct Cell {
  std::string row;  // the method: backend, intersection, lighting
  std::size_t column = 0;
  double milliseconds = 0;          // the whole render, refinement included
  std::size_t referencePixels = 0;  // covered on the reference
  ImageError error;
  // Exact methods only: pixels a dense CPU tessellation covers with all 8
  // neighbours that the exact ray cast missed (Newton found no root).
  std::optional<std::size_t> newtonMisses;
  std::size_t overTolerance = 0;  // interior pixels (not on a silhouette of either image) beyond Tolerance
  // Union of non-finite, hole, extra, Newton-miss and over-tolerance pixels,
  // over the reference's covered pixels: the heat maps' colour.
  double failureShare = 0;
  double beautyMax = 0;   // covered pixels, largest channel
  double beautyMean = 0;  // covered pixels, mean over channels
  // Relative RMSE against a converged reference of the same condition, where
  // the sweep has one (sampled lighting with many more pairs).
  std::optional<double> methodError;
};

// `coverage` (optional) is the dense tessellation that defines Newton misses.
Cell measure(const Image& candidate, const Image& reference, const Image* coverage, const Tolerance& tolerance);

struct Sweep {
  std::string name;       // file stem and CSV key: grazing, roughness, ...
  std::string title;      // report heading
  std::string condition;  // axis label, e.g. "view angle from the normal (deg)"
  std::string setup;      // a paragraph: scene, methods, references, tolerances
  std::vector<double> values;
  std::vector<std::string> valueLabels;
  std::vector<std::string> rows;  // methods, in display order
  std::vector<Cell> cells;
  // The continuous errors shown in a table each, by their CSV column names
  // (relative_rmse, depth_rel_max, normal_rad_max, beauty_max, beauty_mean,
  // method_error)
  // or firefly_ratio (beauty_max / beauty_mean); the reading quotes the first.
  std::vector<std::string> metrics;
};

// Heat map (SVG + PNG), tables and the generated reading, appended to the
// report; images are written to `directory`, referenced relative to it.
void writeSweep(const std::filesystem::path& directory, const Sweep& sweep, Report& report);

// Every sweep's cells, one row each.
void writeStabilityCsv(const std::filesystem::path& path, const std::vector<Sweep>& sweeps);

}  // namespace facet::analysis::bench::stability

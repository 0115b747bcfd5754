// facet bench: every method against time and error, where each fails, how
// each scales, and the peers beside them (README, "Speed against
// accuracy"). Each section lives in its own file and adds its CSVs, charts
// and prose to one Markdown report.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/image/image.h"
#include "engine/renderer.h"

namespace facet::cli::bench {

struct BenchOptions {
  std::filesystem::path output;      // everything is written below it
  std::filesystem::path root = ".";  // the folder holding scenes/ (the source tree)
  bool quick = false;                // the CI smoke run: tiny sizes, few points, one repetition
  int repeats = 5;                   // timed runs per point; the median is reported
  std::string adapter;               // GPU adapter (substring of its name)
};

// The report (report.md in the output folder): sections in the order they
// were added, images and CSVs referenced by paths relative to it.
class Report {
 public:
  void heading(const std::string& title);
  void paragraph(const std::string& text);
  void image(const std::string& relativePath, const std::string& caption);
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  void write(const std::filesystem::path& path) const;  // atomically

 private:
  std::string markdown_;
};

// A CSV with a header row, written atomically; cells are written as given.
void writeCsv(const std::filesystem::path& path, const std::vector<std::string>& header,
              const std::vector<std::vector<std::string>>& rows);

double median(std::vector<double> values);

// Runs `run` (which returns milliseconds) `repeats` times and returns the median.
double medianMilliseconds(int repeats, const std::function<double()>& run);

// A number for a CSV cell or a table: shortest round-trip form.
std::string cell(double value);

// The cost of casting and shading: every stage but refinement and the
// environment's preparation (sampling tables, prefiltering or its cache).
double traceMilliseconds(const RenderReport& report);
double preparationMilliseconds(const RenderReport& report);

// Pixel tests every section judges renders by.
bool covered(const Image& image, int x, int y);
// Every pixel of the 3 x 3 neighbourhood (clipped at the border) covered,
// or every one missed (`coveredState` false).
bool neighbourhoodIs(const Image& image, int x, int y, bool coveredState);
// Beauty and shading normal finite, and the depth where the pixel is covered.
bool finitePixel(const Image& image, int x, int y);
// Angle between two normals; a zero-length one (float underflow far from
// unit scale) has no direction and counts as the worst angle, pi.
double normalAngle(const glm::vec3& a, const glm::vec3& b);

// The PNG exposure, in stops, that puts the reference's mean covered
// radiance at middle grey (0.18): one exposure for every render of a scene.
float middleGreyExposure(const Image& reference);

// A render against a reference of the same scene, pixel by pixel.
struct ImageError {
  double relativeRmse = 0;      // beauty RGB over pixels covered on both, / the reference's mean there
  double maxAbsolute = 0;       // beauty, largest channel difference, same pixels
  double depthRelativeMax = 0;  // |dz| / z over pixels covered on both
  double depthRelativeMean = 0;
  double normalRadiansMax = 0;  // shading normal angle, same pixels
  double normalRadiansMean = 0;
  std::size_t holes = 0;      // covered on the reference, all 8 neighbours too, missed here
  std::size_t extra = 0;      // covered here, not on the reference, all 8 neighbours missed there
  std::size_t nonFinite = 0;  // NaN or Inf in beauty, depth or normal here
  std::size_t compared = 0;   // pixels covered on both
};
ImageError compareToReference(const Image& candidate, const Image& reference);

// The sections, in the order `facet bench` runs them.
void runPareto(const BenchOptions& options, Report& report);
void runStability(const BenchOptions& options, Report& report);
void runScaling(const BenchOptions& options, Report& report);

}  // namespace facet::cli::bench

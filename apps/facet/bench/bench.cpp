#include "bench.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "engine/image/image_io.h"

namespace facet::cli::bench {

void Report::heading(const std::string& title) { markdown_ += "\n## " + title + "\n\n"; }

void Report::paragraph(const std::string& text) { markdown_ += text + "\n\n"; }

void Report::image(const std::string& relativePath, const std::string& caption) {
  markdown_ += "![" + caption + "](" + relativePath + ")\n\n";
}

void Report::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string text = "|";
    for (const std::string& c : cells) text += " " + c + " |";
    return text + "\n";
  };
  markdown_ += line(header);
  markdown_ += line(std::vector<std::string>(header.size(), "---"));
  for (const auto& row : rows) markdown_ += line(row);
  markdown_ += "\n";
}

void Report::write(const std::filesystem::path& path) const {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    out << "# facet bench\n" << markdown_;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  });
}

void writeCsv(const std::filesystem::path& path, const std::vector<std::string>& header,
              const std::vector<std::vector<std::string>>& rows) {
  writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    auto line = [&](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
      out << "\n";
    };
    line(header);
    for (const auto& row : rows) line(row);
    if (!out) throw std::runtime_error("cannot write " + path.string());
  });
}

double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median of no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double medianMilliseconds(int repeats, const std::function<double()>& run) {
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) times.push_back(run());
  return median(times);
}

std::string cell(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

double traceMilliseconds(const RenderReport& report) {
  double total = 0;
  for (const StageTime& stage : report.stages)
    if (stage.name != "refine + BVH" && stage.name != "environment") total += stage.milliseconds;
  return total;
}

double preparationMilliseconds(const RenderReport& report) {
  for (const StageTime& stage : report.stages)
    if (stage.name == "environment") return stage.milliseconds;
  return 0;
}

bool covered(const Image& image, int x, int y) { return image.beauty[image.index(x, y)].a > 0; }

bool neighbourhoodIs(const Image& image, int x, int y, bool coveredState) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = std::clamp(x + dx, 0, image.width - 1), ny = std::clamp(y + dy, 0, image.height - 1);
      if (covered(image, nx, ny) != coveredState) return false;
    }
  return true;
}

bool finitePixel(const Image& image, int x, int y) {
  const std::size_t i = image.index(x, y);
  const glm::vec4& b = image.beauty[i];
  const glm::vec3& n = image.shadingNormal[i];
  return std::isfinite(b.r) && std::isfinite(b.g) && std::isfinite(b.b) && std::isfinite(n.x) && std::isfinite(n.y) &&
         std::isfinite(n.z) && (!covered(image, x, y) || std::isfinite(image.depth[i]));
}

double normalAngle(const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 da(a), db(b);
  const double lengths = glm::length(da) * glm::length(db);
  return lengths > 0 ? std::acos(std::clamp(glm::dot(da, db) / lengths, -1.0, 1.0)) : M_PI;
}

float middleGreyExposure(const Image& reference) {
  double sum = 0;
  std::size_t count = 0;
  for (const glm::vec4& b : reference.beauty)
    if (b.a > 0) {
      sum += (b.r + b.g + b.b) / 3.0;
      ++count;
    }
  const double mean = count ? sum / double(count) : 0;
  return mean > 0 ? float(std::log2(0.18 / mean)) : 0.0f;
}

ImageError compareToReference(const Image& candidate, const Image& reference) {
  if (candidate.width != reference.width || candidate.height != reference.height)
    throw std::invalid_argument("compareToReference: images differ in size");
  ImageError e;
  double squared = 0, sum = 0, depthSum = 0, normalSum = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const std::size_t i = reference.index(x, y);
      const glm::vec4& b = candidate.beauty[i];
      if (!finitePixel(candidate, x, y)) {
        ++e.nonFinite;
        continue;
      }
      const bool here = covered(candidate, x, y), there = covered(reference, x, y);
      if (there && !here && neighbourhoodIs(reference, x, y, true)) ++e.holes;
      if (here && !there && neighbourhoodIs(reference, x, y, false)) ++e.extra;
      if (!here || !there) continue;
      ++e.compared;
      for (int c = 0; c < 3; ++c) {
        const double d = double(b[c]) - double(reference.beauty[i][c]);
        squared += d * d;
        sum += reference.beauty[i][c];
        e.maxAbsolute = std::max(e.maxAbsolute, std::abs(d));
      }
      const double depth = std::abs(double(candidate.depth[i]) - reference.depth[i]) / reference.depth[i];
      e.depthRelativeMax = std::max(e.depthRelativeMax, depth);
      depthSum += depth;
      const double angle = normalAngle(candidate.shadingNormal[i], reference.shadingNormal[i]);
      e.normalRadiansMax = std::max(e.normalRadiansMax, angle);
      normalSum += angle;
    }
  if (e.compared > 0) {
    const double n = double(e.compared);
    e.relativeRmse = sum > 0 ? std::sqrt(squared / (3 * n)) / (sum / (3 * n)) : std::sqrt(squared / (3 * n));
    e.depthRelativeMean = depthSum / n;
    e.normalRadiansMean = normalSum / n;
  }
  return e;
}

}  // namespace facet::cli::bench

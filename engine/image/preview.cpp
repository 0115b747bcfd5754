#include "engine/image/preview.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

#include "engine/image/color.h"

namespace facet {

PreviewEncoder::PreviewEncoder(int width, const PreviewOptions& options, std::uint8_t* rgba)
    : width_(width), options_(options), rgba_(rgba) {}

void PreviewEncoder::push(const glm::vec4* row) {
  std::rotate(rows_.begin(), rows_.begin() + 1, rows_.end());
  rows_[2].assign(row, row + width_);
  if (++pushed_ >= 2) encode(pushed_ - 2);
}

void PreviewEncoder::finish() {
  if (pushed_ == 0) return;
  std::rotate(rows_.begin(), rows_.begin() + 1, rows_.end());
  rows_[2].clear();
  encode(pushed_ - 1);
  pushed_ = 0;
}

void PreviewEncoder::encode(int row) {
  const double scale = std::exp2(double(options_.exposure));
  // What the missed samples of pixel x saw: the mean of its fully missed neighbours.
  const auto missedRadiance = [&](int x) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (const std::vector<glm::vec4>& neighbours : rows_)
      for (int n = std::max(0, x - 1); !neighbours.empty() && n <= std::min(width_ - 1, x + 1); ++n)
        if (neighbours[std::size_t(n)].a <= 0.0f) {
          sum += glm::dvec3(neighbours[std::size_t(n)]);
          ++count;
        }
    return count > 0 ? sum / double(count) : sum;
  };
  std::uint8_t* out = rgba_ + std::size_t(row) * std::size_t(width_) * 4;
  for (int x = 0; x < width_; ++x) {
    const glm::vec4& pixel = rows_[1][std::size_t(x)];
    const double coverage = std::clamp(double(pixel.a), 0.0, 1.0);
    const glm::dvec3 rendered(pixel);
    glm::dvec3 shown = rendered;
    double alpha = 1.0;
    if (options_.straightAlpha || options_.background) {
      glm::dvec3 surface(0.0);
      if (coverage >= 1.0)
        surface = rendered;
      else if (coverage > 0.0)
        surface = glm::max((rendered - (1.0 - coverage) * missedRadiance(x)) / coverage, 0.0);
      if (options_.straightAlpha) {
        shown = surface;
        alpha = coverage;
      } else {
        shown = coverage * surface + (1.0 - coverage) * glm::dvec3(*options_.background);
      }
    }
    const glm::dvec3 encoded = linearToSrgb(toneMap(options_.curve, shown * scale));
    for (int c = 0; c < 3; ++c) out[4 * x + c] = std::uint8_t(std::lround(std::clamp(encoded[c], 0.0, 1.0) * 255.0));
    out[4 * x + 3] = std::uint8_t(std::lround(alpha * 255.0));
  }
}

std::vector<std::uint8_t> previewPixels(const std::vector<glm::vec4>& beauty, int width, int height,
                                        const PreviewOptions& options) {
  std::vector<std::uint8_t> rgba(std::size_t(width) * std::size_t(height) * 4);
  PreviewEncoder encoder(width, options, rgba.data());
  for (int y = 0; y < height; ++y) encoder.push(beauty.data() + std::size_t(y) * std::size_t(width));
  encoder.finish();
  return rgba;
}

}  // namespace facet

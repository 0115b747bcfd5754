#include "engine/image/sample_rounds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace facet {

PixelRect TileGrid::tile(int index) const {
  const int x0 = (index % columns()) * size, y0 = (index / columns()) * size;
  return {x0, y0, std::min(width, x0 + size), std::min(height, y0 + size)};
}

double luminance(const glm::vec4& rgba) {
  return 0.2126 * double(rgba.r) + 0.7152 * double(rgba.g) + 0.0722 * double(rgba.b);
}

double judgedLuminance(const glm::vec4& rgba) { return std::min(luminance(rgba), kDisplayWhite); }

SampleRounds::SampleRounds(int width, int height, int tileSize)
    : grid_{width, height, tileSize},
      rounds_(std::size_t(grid_.count()), 0),
      sum_(std::size_t(width) * std::size_t(height), glm::dvec4(0.0)),
      luminanceSum_(sum_.size(), 0.0),
      luminanceSquares_(sum_.size(), 0.0) {
  if (width < 1 || height < 1 || tileSize < 1)
    throw std::invalid_argument("sample rounds need a positive image and tile size");
}

void SampleRounds::add(const Image& round, const PixelRect& window, const std::vector<int>& tiles) {
  if (round.width != window.width() || round.height != window.height())
    throw std::invalid_argument("a round's image is not the size of its window " + window.text());
  for (int t : tiles) {
    if (t < 0 || t >= grid_.count()) throw std::invalid_argument("no tile " + std::to_string(t));
    const PixelRect r = grid_.tile(t);
    if (r.x0 < window.x0 || r.y0 < window.y0 || r.x1 > window.x1 || r.y1 > window.y1)
      throw std::invalid_argument("tile " + r.text() + " is not inside the round's window " + window.text());
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const glm::vec4 v = round.beauty[round.index(x - window.x0, y - window.y0)];
        const std::size_t p = std::size_t(y) * std::size_t(grid_.width) + std::size_t(x);
        const double l = judgedLuminance(v);
        sum_[p] += glm::dvec4(v);
        luminanceSum_[p] += l;
        luminanceSquares_[p] += l * l;
      }
    ++rounds_[std::size_t(t)];
  }
}

double SampleRounds::error(int tile) const {
  const int n = rounds_[std::size_t(tile)];
  if (n < 2) return std::numeric_limits<double>::infinity();
  const PixelRect r = grid_.tile(tile);
  double variance = 0.0, mean = 0.0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(grid_.width) + std::size_t(x);
      const double m = luminanceSum_[p] / n;
      // The unbiased sample variance of the rounds, then of their mean.
      variance += std::max(0.0, luminanceSquares_[p] - n * m * m) / (n - 1) / n;
      mean += m;
    }
  const double pixels = double(r.pixelCount());
  return std::sqrt(variance / pixels) / std::max(mean / pixels, kLuminanceFloor);
}

std::vector<glm::vec4> SampleRounds::beauty() const {
  std::vector<glm::vec4> pixels(sum_.size(), glm::vec4(0.0f));
  for (int t = 0; t < grid_.count(); ++t) {
    const int n = rounds_[std::size_t(t)];
    if (n == 0) continue;
    const PixelRect r = grid_.tile(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const std::size_t p = std::size_t(y) * std::size_t(grid_.width) + std::size_t(x);
        pixels[p] = glm::vec4(sum_[p] / double(n));
      }
  }
  return pixels;
}

}  // namespace facet

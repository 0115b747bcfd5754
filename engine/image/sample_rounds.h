// The noise of a render estimated from independent rounds of samples, per
// tile (docs/preview-stage.md, "Adaptive sampling"). Each round is a whole
// estimate of its pixels with its own random numbers; a pixel's value is the
// mean of its rounds, and the spread of the rounds about that mean is what
// estimates the mean's standard error.
#pragma once

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"

namespace facet {

// The image cut into square tiles of `size` pixels (smaller at the right and
// bottom edges), numbered row by row.
struct TileGrid {
  int width = 0, height = 0, size = 16;

  int columns() const { return (width + size - 1) / size; }
  int rows() const { return (height + size - 1) / size; }
  int count() const { return columns() * rows(); }
  PixelRect tile(int index) const;
};

// A tile's error is judged against its mean luminance, but never against
// less than this: dark tiles are judged by their absolute error there.
inline constexpr double kLuminanceFloor = 0.05;

// The luminance a picture shows as white. A round's pixel brighter than
// this counts as this: the spread of a lamp's edge, 100 times white, or of
// a highlight that the tone curve shows white anyway, is noise nobody sees,
// and judged unclipped it would keep a tile running to the sample cap.
inline constexpr double kDisplayWhite = 1.0;

class SampleRounds {
 public:
  SampleRounds(int width, int height, int tileSize);

  const TileGrid& grid() const { return grid_; }

  // Adds a round's beauty to the pixels of `tiles`; `round` holds the pixels
  // of `window` of the full image, which must contain every tile listed.
  // Throws std::invalid_argument otherwise.
  void add(const Image& round, const PixelRect& window, const std::vector<int>& tiles);

  int rounds(int tile) const { return rounds_[std::size_t(tile)]; }

  // The standard error of the tile's pixels' means, as the root mean square
  // over the tile of each pixel's s / sqrt(n) (s the sample standard
  // deviation of its n rounds' judgedLuminance), relative to the tile's
  // mean of it or kLuminanceFloor, whichever is larger. Infinite below two
  // rounds.
  double error(int tile) const;

  // Each pixel's mean over its rounds (RGB and coverage); zero where none.
  std::vector<glm::vec4> beauty() const;

 private:
  TileGrid grid_;
  std::vector<int> rounds_;           // per tile
  std::vector<glm::dvec4> sum_;       // per pixel: RGBA summed over rounds
  std::vector<double> luminanceSum_;  // per pixel: Y and Y^2 summed over rounds
  std::vector<double> luminanceSquares_;
};

// Rec. 709 luminance of linear RGB.
double luminance(const glm::vec4& rgba);

// The luminance a tile's noise is judged by: clipped at kDisplayWhite.
double judgedLuminance(const glm::vec4& rgba);

}  // namespace facet

// A rectangle of pixels of a full image, half-open: x0 <= x < x1, y0 <= y < y1,
// row 0 at the top. Crops and tiles are such rectangles of the display window.
#pragma once

#include <cstdint>
#include <string>

namespace facet {

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  static PixelRect whole(int width, int height) { return {0, 0, width, height}; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  std::uint64_t pixelCount() const { return std::uint64_t(width()) * std::uint64_t(height()); }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool inside(int width, int height) const { return x0 >= 0 && y0 >= 0 && x1 <= width && y1 <= height; }
  bool overlaps(const PixelRect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  bool operator==(const PixelRect& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
  std::string text() const {
    return std::to_string(x0) + "," + std::to_string(y0) + "," + std::to_string(x1) + "," + std::to_string(y1);
  }
};

// Tile `index` of `count` (0-based): a band of whole rows, the rows split as
// evenly as integers allow. Bands keep each tile one contiguous run of pixels
// for the GPU's bands and whole scanlines for the merge.
inline PixelRect tileRows(int width, int height, int index, int count) {
  const auto row = [&](int i) { return int(std::int64_t(height) * i / count); };
  return {0, row(index), width, row(index + 1)};
}

}  // namespace facet

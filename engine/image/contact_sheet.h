// A contact sheet: several 8-bit RGBA images of one size in a grid, each
// with its label in a strip under it, drawn with stb_easy_font's quads
// (docs/preview-stage.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/image/pixel_rect.h"

namespace facet {

// Where each cell and its label lie on the sheet. Cells run left to right,
// then top to bottom; `gap` pixels of the strip colour surround each one.
struct ContactSheetLayout {
  int count = 0;
  int columns = 0, rows = 0;
  int cellWidth = 0, cellHeight = 0;
  int textScale = 1;  // font units to pixels: stb_easy_font's glyphs are 7 units tall
  int labelHeight = 0;
  int gap = 0;

  int width() const { return columns * (cellWidth + gap) + gap; }
  int height() const { return rows * (cellHeight + labelHeight + gap) + gap; }
  PixelRect cell(int index) const;   // the image of cell `index`
  PixelRect label(int index) const;  // the strip under it
};

// `count` cells of cellWidth x cellHeight in `columns` columns (0: the
// smallest number that makes the grid at least as wide as tall), the text
// scaled with the cell's width. Throws std::invalid_argument for an empty
// sheet or a non-positive size.
ContactSheetLayout contactSheetLayout(int count, int cellWidth, int cellHeight, int columns = 0);

struct ContactCell {
  std::vector<std::uint8_t> rgba;  // cellWidth x cellHeight, row 0 at the top
  std::string label;               // printable ASCII; shortened with "..." to fit its strip
};

inline constexpr std::uint8_t kSheetBackground = 40;  // grey of the strips and gaps
inline constexpr std::uint8_t kSheetText = 235;       // grey of the labels

// The sheet's opaque RGBA pixels. Throws std::invalid_argument where the
// cells are not layout.count images of the layout's cell size.
std::vector<std::uint8_t> composeContactSheet(const ContactSheetLayout& layout, const std::vector<ContactCell>& cells);

// The label as drawn: non-printable characters as '?', shortened with
// "..." until it is at most `widthPixels` wide at `textScale`.
std::string fittedLabel(const std::string& label, int widthPixels, int textScale);

}  // namespace facet

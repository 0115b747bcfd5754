#include "engine/image/contact_sheet.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace facet {
namespace {

// stb_easy_font's glyphs stand 7 units tall from the pen's y (Sean Barrett's
// header: "descenders" reach 2 units lower); the strip keeps 3 units of air
// above and below them.
constexpr int kGlyphUnits = 9;
constexpr int kStripUnits = kGlyphUnits + 6;

int textWidthUnits(std::string text) { return stb_easy_font_width(text.data()); }

struct Vertex {
  float x, y, z;
  std::uint8_t colour[4];
};
static_assert(sizeof(Vertex) == 16, "stb_easy_font writes 16-byte vertices");

// Fills each of the text's quads, scaled by `scale` about the pen at (x, y)
// in pixels, clipped to `clip`.
void drawText(const std::string& text, int x, int y, int scale, const PixelRect& clip, int sheetWidth,
              std::vector<std::uint8_t>& rgba) {
  std::string buffer = text;
  std::vector<Vertex> vertices(text.size() * 64 + 64);  // stb needs about 270 bytes per character
  const int quads =
      stb_easy_font_print(0, 0, buffer.data(), nullptr, vertices.data(), int(vertices.size() * sizeof(Vertex)));
  for (int q = 0; q < quads; ++q) {
    const Vertex* v = &vertices[std::size_t(q) * 4];
    float minX = v[0].x, maxX = v[0].x, minY = v[0].y, maxY = v[0].y;
    for (int k = 1; k < 4; ++k) {
      minX = std::min(minX, v[k].x), maxX = std::max(maxX, v[k].x);
      minY = std::min(minY, v[k].y), maxY = std::max(maxY, v[k].y);
    }
    const int x0 = std::max(clip.x0, x + int(std::lround(minX * float(scale))));
    const int x1 = std::min(clip.x1, x + int(std::lround(maxX * float(scale))));
    const int y0 = std::max(clip.y0, y + int(std::lround(minY * float(scale))));
    const int y1 = std::min(clip.y1, y + int(std::lround(maxY * float(scale))));
    for (int py = y0; py < y1; ++py)
      for (int px = x0; px < x1; ++px) {
        std::uint8_t* p = &rgba[4 * (std::size_t(py) * std::size_t(sheetWidth) + std::size_t(px))];
        p[0] = p[1] = p[2] = kSheetText;
      }
  }
}

}  // namespace

PixelRect ContactSheetLayout::cell(int index) const {
  const int column = index % columns, row = index / columns;
  const int x = gap + column * (cellWidth + gap), y = gap + row * (cellHeight + labelHeight + gap);
  return {x, y, x + cellWidth, y + cellHeight};
}

PixelRect ContactSheetLayout::label(int index) const {
  const PixelRect image = cell(index);
  return {image.x0, image.y1, image.x1, image.y1 + labelHeight};
}

ContactSheetLayout contactSheetLayout(int count, int cellWidth, int cellHeight, int columns) {
  if (count < 1) throw std::invalid_argument("a contact sheet needs at least one image");
  if (cellWidth < 1 || cellHeight < 1) throw std::invalid_argument("a contact sheet's cells need a positive size");
  if (columns < 0) throw std::invalid_argument("a contact sheet's columns must not be negative");
  ContactSheetLayout layout;
  layout.count = count;
  layout.columns = columns > 0 ? std::min(columns, count) : int(std::ceil(std::sqrt(double(count))));
  layout.rows = (count + layout.columns - 1) / layout.columns;
  layout.cellWidth = cellWidth;
  layout.cellHeight = cellHeight;
  layout.textScale = std::max(1, cellWidth / 160);
  layout.labelHeight = kStripUnits * layout.textScale;
  layout.gap = 2 * layout.textScale;
  return layout;
}

std::string fittedLabel(const std::string& label, int widthPixels, int textScale) {
  std::string text = label;
  for (char& c : text)
    if (c < 32 || c > 126) c = '?';
  const int units = widthPixels / textScale;
  if (textWidthUnits(text) <= units) return text;
  while (!text.empty() && textWidthUnits(text + "...") > units) text.pop_back();
  return text.empty() ? std::string() : text + "...";
}

std::vector<std::uint8_t> composeContactSheet(const ContactSheetLayout& layout, const std::vector<ContactCell>& cells) {
  if (int(cells.size()) != layout.count)
    throw std::invalid_argument("a contact sheet of " + std::to_string(layout.count) + " cells was given " +
                                std::to_string(cells.size()) + " images");
  const std::size_t cellBytes = 4 * std::size_t(layout.cellWidth) * std::size_t(layout.cellHeight);
  const int width = layout.width();
  std::vector<std::uint8_t> rgba(4 * std::size_t(width) * std::size_t(layout.height()), kSheetBackground);
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  for (int i = 0; i < layout.count; ++i) {
    const ContactCell& c = cells[std::size_t(i)];
    if (c.rgba.size() != cellBytes)
      throw std::invalid_argument("contact sheet image " + std::to_string(i) + " ('" + c.label + "') is not " +
                                  std::to_string(layout.cellWidth) + " x " + std::to_string(layout.cellHeight));
    const PixelRect image = layout.cell(i);
    for (int y = 0; y < layout.cellHeight; ++y)
      std::copy_n(&c.rgba[4 * std::size_t(y) * std::size_t(layout.cellWidth)], 4 * std::size_t(layout.cellWidth),
                  &rgba[4 * (std::size_t(image.y0 + y) * std::size_t(width) + std::size_t(image.x0))]);
    const PixelRect strip = layout.label(i);
    const std::string text = fittedLabel(c.label, strip.width(), layout.textScale);
    const int textWidth = textWidthUnits(text) * layout.textScale;
    drawText(text, strip.x0 + (strip.width() - textWidth) / 2, strip.y0 + 3 * layout.textScale, layout.textScale, strip,
             width, rgba);
  }
  return rgba;
}

}  // namespace facet

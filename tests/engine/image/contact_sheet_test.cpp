#include "engine/image/contact_sheet.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace facet {
namespace {

// A cell of one colour that neither the strips nor the text use.
ContactCell solidCell(const ContactSheetLayout& layout, std::uint8_t red, std::string label) {
  std::vector<std::uint8_t> rgba(4 * std::size_t(layout.cellWidth) * std::size_t(layout.cellHeight));
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    rgba[i] = red;
    rgba[i + 1] = 7;
    rgba[i + 2] = 9;
    rgba[i + 3] = 255;
  }
  return {rgba, std::move(label)};
}

bool inside(const PixelRect& r, int x, int y) { return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1; }

TEST(ContactSheet, LaysCellsOutInAGridWithAStripUnderEach) {
  const ContactSheetLayout layout = contactSheetLayout(5, 64, 48);
  EXPECT_EQ(layout.columns, 3);
  EXPECT_EQ(layout.rows, 2);
  EXPECT_EQ(layout.width(), 3 * 64 + 4 * layout.gap);
  EXPECT_EQ(layout.height(), 2 * (48 + layout.labelHeight) + 3 * layout.gap);
  EXPECT_GE(layout.labelHeight, 9 * layout.textScale) << "the glyphs fit their strip";
  for (int i = 0; i < layout.count; ++i) {
    const PixelRect cell = layout.cell(i), label = layout.label(i);
    EXPECT_EQ(cell.width(), 64);
    EXPECT_EQ(cell.height(), 48);
    EXPECT_EQ(label.x0, cell.x0);
    EXPECT_EQ(label.x1, cell.x1);
    EXPECT_EQ(label.y0, cell.y1) << "the label is right under its image";
    EXPECT_TRUE(label.inside(layout.width(), layout.height()));
    for (int j = 0; j < i; ++j) {
      EXPECT_FALSE(cell.overlaps(layout.cell(j)));
      EXPECT_FALSE(label.overlaps(layout.cell(j)));
    }
  }
  EXPECT_EQ(layout.cell(3).x0, layout.cell(0).x0) << "the fourth cell starts the second row";
  EXPECT_GT(layout.cell(3).y0, layout.label(0).y1);
  EXPECT_EQ(contactSheetLayout(4, 10, 10, 4).rows, 1);
  EXPECT_EQ(contactSheetLayout(2, 10, 10, 8).columns, 2) << "no empty columns";
}

TEST(ContactSheet, TextScalesWithTheCell) {
  EXPECT_EQ(contactSheetLayout(1, 128, 128).textScale, 1);
  EXPECT_EQ(contactSheetLayout(1, 512, 512).textScale, 3);
}

TEST(ContactSheet, CopiesEachImageAndDrawsLabelsOnlyInTheirStrips) {
  const ContactSheetLayout layout = contactSheetLayout(4, 96, 64);
  std::vector<ContactCell> cells;
  for (int i = 0; i < 4; ++i)
    cells.push_back(solidCell(layout, std::uint8_t(100 + 30 * i), "gold " + std::to_string(i)));
  const std::vector<std::uint8_t> sheet = composeContactSheet(layout, cells);
  ASSERT_EQ(sheet.size(), 4 * std::size_t(layout.width()) * std::size_t(layout.height()));
  std::vector<int> textPixels(4, 0);
  for (int y = 0; y < layout.height(); ++y)
    for (int x = 0; x < layout.width(); ++x) {
      const std::uint8_t* p = &sheet[4 * (std::size_t(y) * std::size_t(layout.width()) + std::size_t(x))];
      ASSERT_EQ(p[3], 255) << "opaque";
      int owner = -1;
      for (int i = 0; i < 4; ++i)
        if (inside(layout.cell(i), x, y)) owner = i;
      if (owner >= 0) {
        ASSERT_EQ(p[0], 100 + 30 * owner) << "cell " << owner << " at " << x << "," << y;
        ASSERT_EQ(p[1], 7);
        continue;
      }
      if (p[0] == kSheetText) {
        int strip = -1;
        for (int i = 0; i < 4; ++i)
          if (inside(layout.label(i), x, y)) strip = i;
        ASSERT_GE(strip, 0) << "text outside every label strip at " << x << "," << y;
        ++textPixels[std::size_t(strip)];
      } else {
        ASSERT_EQ(p[0], kSheetBackground) << x << "," << y;
      }
    }
  for (int i = 0; i < 4; ++i) EXPECT_GT(textPixels[std::size_t(i)], 20) << "label " << i << " is drawn";
}

TEST(ContactSheet, ShortensLabelsToTheirStrip) {
  const std::string longName(200, 'W');
  const std::string fitted = fittedLabel(longName, 96, 1);
  EXPECT_LT(fitted.size(), longName.size());
  EXPECT_EQ(fitted.substr(fitted.size() - 3), "...");
  EXPECT_EQ(fittedLabel("gold", 96, 1), "gold");
  EXPECT_EQ(fittedLabel("a\tb", 96, 1), "a?b") << "only printable ASCII is drawn";
  // A long label still draws nothing outside its strip.
  const ContactSheetLayout layout = contactSheetLayout(2, 40, 20);
  const std::vector<std::uint8_t> sheet =
      composeContactSheet(layout, {solidCell(layout, 1, longName), solidCell(layout, 2, longName)});
  for (int y = 0; y < layout.height(); ++y)
    for (int x = 0; x < layout.width(); ++x) {
      if (sheet[4 * (std::size_t(y) * std::size_t(layout.width()) + std::size_t(x))] != kSheetText) continue;
      ASSERT_TRUE(inside(layout.label(0), x, y) || inside(layout.label(1), x, y)) << x << "," << y;
    }
}

TEST(ContactSheet, RefusesCellsThatDoNotFitTheLayout) {
  const ContactSheetLayout layout = contactSheetLayout(2, 8, 8);
  EXPECT_THROW(composeContactSheet(layout, {solidCell(layout, 1, "a")}), std::invalid_argument);
  ContactCell wrong = solidCell(layout, 1, "b");
  wrong.rgba.resize(12);
  EXPECT_THROW(composeContactSheet(layout, {solidCell(layout, 1, "a"), wrong}), std::invalid_argument);
  EXPECT_THROW(contactSheetLayout(0, 8, 8), std::invalid_argument);
  EXPECT_THROW(contactSheetLayout(1, 0, 8), std::invalid_argument);
}

}  // namespace
}  // namespace facet

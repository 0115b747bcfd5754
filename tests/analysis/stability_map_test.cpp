// The stability heat map is a valid SVG whose text, its title and the
// colour scale's labels included, lies inside the canvas.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "analysis/bench/stability_map.h"
#include "tests/support/temp_dir.h"

namespace facet::analysis::bench::stability {
namespace {

class HeatMap : public facet::testing::TempDirTest {};

struct Text {
  double x = 0, y = 0, fontSize = 0;
  std::string anchor, content;
};

// gnuplot's SVG writes each text as <g transform="translate(x,y)" ...
// font-size="s" text-anchor="a"> <text>content</text>.
std::vector<Text> texts(const std::string& svg) {
  const std::regex pattern(
      "<g "
      "transform=\"translate\\(([-0-9.]+),([-0-9.]+)\\)\"[^>]*font-size=\"([0-9.]+)\"\\s*text-anchor=\"(\\w+)\"[^>]*>"
      "\\s*<text>([^<]*)</text>");
  std::vector<Text> found;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), pattern); it != std::sregex_iterator(); ++it)
    found.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), (*it)[4], (*it)[5]});
  return found;
}

TEST_F(HeatMap, TitleAndLabelsFitTheCanvas) {
  Sweep sweep;
  sweep.name = "stability_test";
  sweep.title = "a sweep with a rather long title to test the layout";
  sweep.condition = "the condition";
  sweep.values = {0, 1, 2};
  sweep.valueLabels = {"0", "1", "2"};
  sweep.rows = {"gpu tess k=8 prefiltered", "cpu exact"};
  sweep.metrics = {"relative_rmse"};
  for (const std::string& row : sweep.rows)
    for (std::size_t column = 0; column < sweep.values.size(); ++column) {
      Cell c;
      c.row = row;
      c.column = column;
      c.referencePixels = 100;
      c.error.holes = column;
      c.failureShare = 0.01 * double(column);
      sweep.cells.push_back(c);
    }
  Report report;
  writeSweep(dir_, sweep, report);

  std::ifstream file(dir_ / "stability_test.svg");
  std::stringstream buffer;
  buffer << file.rdbuf();
  const std::string svg = buffer.str();
  ASSERT_NE(svg.find("<svg"), std::string::npos);
  ASSERT_NE(svg.find("</svg>"), std::string::npos);
  std::smatch box;
  ASSERT_TRUE(std::regex_search(svg, box, std::regex("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\"")));
  const double width = std::stod(box[1]), height = std::stod(box[2]);

  const std::vector<Text> all = texts(svg);
  bool sawTitle = false, sawScale = false;
  for (const Text& t : all) {
    // A generous estimate of the text's extent: 0.6 em a character.
    const double extent = 0.6 * t.fontSize * double(t.content.size());
    const double left = t.anchor == "end" ? t.x - extent : t.anchor == "middle" ? t.x - extent / 2 : t.x;
    EXPECT_GE(left, 0.0) << t.content;
    EXPECT_LE(left + extent, width) << t.content;
    EXPECT_GE(t.y - t.fontSize, 0.0) << t.content;
    EXPECT_LE(t.y, height) << t.content;
    sawTitle = sawTitle || t.content == sweep.title + ": share of failing pixels";
    sawScale = sawScale || t.content == "&lt;=0.01%" || t.content == "<=0.01%";
  }
  EXPECT_TRUE(sawTitle);
  EXPECT_TRUE(sawScale);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "stability_test.png"));
}

}  // namespace
}  // namespace facet::analysis::bench::stability

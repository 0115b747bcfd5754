#include "analysis/parity_heatmap.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace facet::analysis {
namespace {

// A 3 x 5 pixel font, enough for AOV names and numbers: each glyph is five
// rows of three bits, top row first, one octal digit a row.
constexpr const char* kGlyphs = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ .,:/+-()=<>%_";
constexpr std::uint16_t kRows[] = {
    075557, 026227, 071747, 071317, 055711, 074717, 074757, 071222, 075757, 075717,  // 0-9
    025755, 065656, 034443, 065556, 074647, 074644, 034553, 055755, 072227, 011152,  // A-J
    055655, 044447, 057755, 065555, 025552, 065644, 025563, 065655, 034216, 072222,  // K-T
    055557, 055552, 055775, 055255, 055222, 071247,                                  // U-Z
    000000, 000002, 000024, 002020, 011244, 002720, 000700, 012221, 042224, 007070,  // space to =
    012421, 042124, 051245, 000007};                                                 // < > % _

constexpr int kScale = 2;  // font pixels per glyph pixel
constexpr int kAdvance = 4 * kScale;
constexpr int kLine = 7 * kScale;

struct Canvas {
  int width, height;
  std::vector<std::uint8_t> rgba;

  Canvas(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0) {
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  }
  void set(int x, int y, const glm::vec3& colour) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* p = &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::lround(255.0f * std::clamp(colour[c], 0.0f, 1.0f)));
  }
  void fill(int x0, int y0, int w, int h, const glm::vec3& colour) {
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) set(x, y, colour);
  }
  void text(int x, int y, const std::string& words) {
    for (char c : words) {
      const char* at = std::strchr(kGlyphs, std::toupper(static_cast<unsigned char>(c)));
      const std::uint16_t rows = at && *at ? kRows[at - kGlyphs] : kRows[std::strchr(kGlyphs, '_') - kGlyphs];
      for (int r = 0; r < 5; ++r)
        for (int b = 0; b < 3; ++b)
          if (rows >> (3 * (4 - r)) & (4 >> b)) fill(x + b * kScale, y + r * kScale, kScale, kScale, glm::vec3(1));
      x += kAdvance;
    }
  }
};

glm::vec3 heatColour(float e) {
  if (e < 0.0f) return {0.0f, 0.2f, 1.0f};  // coverage differs
  if (e <= 1.0f) return {0.0f, e, 0.0f};
  return {std::min(1.0f, 0.3f + 0.7f * std::log10(e)), 0.0f, 0.0f};
}

}  // namespace

OutputFile heatmapFile(const std::filesystem::path& path, const ParityReport& report, const std::string& aov) {
  const std::vector<float>* heat = &report.heat;
  std::string caption = "largest of depth, shading normal, beauty: error / tolerance";
  if (!aov.empty()) {
    auto named = std::find_if(report.aovs.begin(), report.aovs.end(),
                              [&](const AovParity& a) { return a.name == aov && a.gated; });
    if (named == report.aovs.end())
      throw std::invalid_argument("--heatmap-aov '" + aov + "': not a gated AOV (depth, shading normal, beauty)");
    heat = &named->heat;
    caption = aov + ": error / tolerance";
    if (named->test != "tolerance") caption = aov + ": log p / log alpha (paired t-test)";
  }
  // Enlarged by a whole factor until the legend's lines fit under it.
  const int legendWidth = std::max(50, int(caption.size()) + 1) * kAdvance;
  const int zoom = std::clamp((legendWidth + report.width - 1) / std::max(report.width, 1), 1, 16);
  const int width = std::max(report.width * zoom, legendWidth), top = report.height * zoom;
  auto drawn = std::make_shared<Canvas>(width, top + 5 * kLine);
  Canvas& canvas = *drawn;
  for (int y = 0; y < top; ++y)
    for (int x = 0; x < report.width * zoom; ++x)
      canvas.set(x, y, heatColour((*heat)[std::size_t(y / zoom) * std::size_t(report.width) + std::size_t(x / zoom)]));
  int y = top + kLine / 2;
  canvas.text(4, y, caption);
  y += kLine;
  // The scale: 0 to 1 linear, then 1 to 10 by decades, as heatColour maps them.
  const int bar = 25 * kAdvance, x0 = 4;
  for (int x = 0; x < bar; ++x) {
    const float s = float(x) / float(bar - 1);
    canvas.fill(x0 + x, y, 1, kLine - 2, heatColour(s < 0.5f ? 2 * s : std::pow(10.0f, 2 * s - 1)));
  }
  y += kLine;
  canvas.text(x0, y, "0");
  canvas.text(x0 + bar / 2 - kAdvance / 2, y, "1");
  canvas.text(x0 + bar - 3 * kAdvance, y, "10+");
  y += kLine;
  canvas.fill(x0, y, 5 * kScale, 5 * kScale, heatColour(-1));
  canvas.text(x0 + 4 * kAdvance / 2 + 2 * kScale, y, "coverage differs");
  return {path, [drawn](const std::filesystem::path& to) {
            rgbaPngFile(to, drawn->width, drawn->height, drawn->rgba).write(to);
          }};
}

}  // namespace facet::analysis

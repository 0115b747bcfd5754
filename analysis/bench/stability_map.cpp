#include "analysis/bench/stability_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "analysis/gnuplot.h"

namespace facet::analysis::bench::stability {
namespace {

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

std::string percent(double share) {
  if (share <= 0) return "0";
  char text[32];
  std::snprintf(text, sizeof text, share < 0.01 ? "%.2g%%" : "%.0f%%", 100 * share);
  return text;
}

double metricValue(const Cell& c, const std::string& metric) {
  if (metric == "relative_rmse") return c.error.relativeRmse;
  if (metric == "depth_rel_max") return c.error.depthRelativeMax;
  if (metric == "normal_rad_max") return c.error.normalRadiansMax;
  if (metric == "beauty_max") return c.beautyMax;
  if (metric == "beauty_mean") return c.beautyMean;
  if (metric == "firefly_ratio") return c.beautyMean > 0 ? c.beautyMax / c.beautyMean : 0;
  if (metric == "method_error") return c.methodError.value_or(std::nan(""));
  throw std::logic_error("stability: unknown metric " + metric);
}

const Cell* find(const Sweep& sweep, const std::string& row, std::size_t column) {
  for (const Cell& c : sweep.cells)
    if (c.row == row && c.column == column) return &c;
  return nullptr;
}

// The failure kinds one cell shows, tersely: N non-finite, H holes, X extra,
// M Newton misses, T over tolerance.
std::string flags(const Cell& c) {
  std::string text;
  if (c.error.nonFinite) text += "N";
  if (c.error.holes) text += "H";
  if (c.error.extra) text += "X";
  if (c.newtonMisses.value_or(0)) text += "M";
  if (c.overTolerance) text += "T";
  return text;
}

std::string tableCell(const Cell& c) {
  if (c.failureShare <= 0) return "ok";
  std::vector<std::string> parts;
  if (c.error.nonFinite) parts.push_back(std::to_string(c.error.nonFinite) + " NaN/Inf");
  if (c.error.holes) parts.push_back(std::to_string(c.error.holes) + " holes");
  if (c.error.extra) parts.push_back(std::to_string(c.error.extra) + " extra");
  if (c.newtonMisses.value_or(0)) parts.push_back(std::to_string(*c.newtonMisses) + " Newton");
  if (c.overTolerance) parts.push_back(std::to_string(c.overTolerance) + " over tol.");
  std::string text = "**" + percent(c.failureShare) + "**:";
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : " ") + parts[i];
  return text;
}

// The canvas, in pixels, laid out from its text: gnuplot centres a title on
// the plot, not the canvas, and does not widen a margin for long tick or
// colour-box labels, so the margins are set here from the labels' lengths.
struct HeatMapLayout {
  static constexpr double kCharWidth = 9;  // of the 12-point terminal font, rounded up
  static constexpr double kLineHeight = 18;
  static constexpr double kColumnWidth = 78, kRowHeight = 34;
  double width = 0, height = 0;  // whole pixels
  double left = 0, plotWidth = 0, top = 0, plotHeight = 0;

  HeatMapLayout(const std::vector<std::string>& titleLines, const std::vector<std::string>& rowLabels,
                const std::vector<std::string>& columnLabels, const std::string& xLabel,
                const std::vector<std::string>& scaleLabels) {
    auto longest = [](const std::vector<std::string>& texts) {
      std::size_t n = 0;
      for (const std::string& t : texts) n = std::max(n, t.size());
      return double(n) * kCharWidth;
    };
    left = longest(rowLabels) + 2 * kCharWidth;
    plotWidth =
        std::max(kColumnWidth * double(columnLabels.size()), longest(columnLabels) * double(columnLabels.size()));
    // Colour box, a gap, its labels and a margin.
    const double right = 2 * kCharWidth + 16 + 2 * kCharWidth + longest(scaleLabels) + 2 * kCharWidth;
    width = std::ceil(std::max({left + plotWidth + right, longest(titleLines) + 4 * kCharWidth,
                                left + std::max(plotWidth, longest({xLabel})) + 2 * kCharWidth}));
    left += (width - left - plotWidth - right) / 2;
    top = (double(titleLines.size()) + 1) * kLineHeight;
    plotHeight = kRowHeight * double(rowLabels.size());
    const double bottom = 4 * kLineHeight;  // tick labels and the axis label
    height = std::ceil(top + plotHeight + bottom);
  }

  // gnuplot's screen coordinates: 0 to 1 from the bottom left.
  double screenX(double pixels) const { return pixels / width; }
  double screenY(double pixels) const { return 1 - pixels / height; }
};

void writeHeatMap(const std::filesystem::path& directory, const Sweep& sweep) {
  std::ostringstream data, script;
  // Log colour scale from 1e-4 (and 0) to 1; the cell's text keeps the
  // exact share and the kinds of failure.
  for (std::size_t r = 0; r < sweep.rows.size(); ++r)
    for (std::size_t c = 0; c < sweep.values.size(); ++c) {
      const Cell* cell = find(sweep, sweep.rows[r], c);
      const double share = cell ? cell->failureShare : 0;
      std::string label = "-";
      if (cell) {
        label = percent(share);
        if (const std::string kinds = flags(*cell); !kinds.empty()) label.append(" ").append(kinds);
      }
      data << c << " " << r << " " << std::log10(std::max(share, 1e-4)) << " \"" << label << "\"\n";
    }
  const std::vector<std::string> title{sweep.title + ": share of failing pixels",
                                       "N non-finite, H holes, X extra, M Newton misses, T over tolerance"};
  const HeatMapLayout layout(title, sweep.rows, sweep.valueLabels, sweep.condition,
                             {"<=0.01%", "0.1%", "1%", "10%", "100%"});
  const double right = layout.left + layout.plotWidth, bottom = layout.top + layout.plotHeight;
  script << "set output OUTPUT\nset termoption noenhanced\n";
  for (std::size_t line = 0; line < title.size(); ++line)
    script << "set label " << line + 1 << " \"" << title[line] << "\" at screen 0.5, screen "
           << layout.screenY(HeatMapLayout::kLineHeight * double(line + 1)) << " center\n";
  script << "set lmargin at screen " << layout.screenX(layout.left) << "\nset rmargin at screen "
         << layout.screenX(right) << "\nset tmargin at screen " << layout.screenY(layout.top)
         << "\nset bmargin at screen " << layout.screenY(bottom) << "\n"
         << "set colorbox user origin screen " << layout.screenX(right + 2 * HeatMapLayout::kCharWidth) << ", screen "
         << layout.screenY(bottom) << " size screen " << 16 / layout.width << ", screen "
         << layout.plotHeight / layout.height << "\n"
         << "set xrange [-0.5:" << sweep.values.size() - 0.5 << "]\nset yrange [" << sweep.rows.size() - 0.5
         << ":-0.5]\nset cbrange [-4:0]\n"
         << "set cbtics ('<=0.01%%' -4, '0.1%%' -3, '1%%' -2, '10%%' -1, '100%%' 0)\n"
         << "set palette defined (-4 '#f7fbff', -3 '#fee8c8', -2 '#fdbb84', -1 '#e34a33', 0 '#7f0000')\n"
         << "set xlabel \"" << sweep.condition << "\"\nset tics scale 0\nset xtics (";
  for (std::size_t c = 0; c < sweep.values.size(); ++c)
    script << (c ? ", " : "") << "\"" << sweep.valueLabels[c] << "\" " << c;
  script << ")\nset ytics (";
  for (std::size_t r = 0; r < sweep.rows.size(); ++r) script << (r ? ", " : "") << "\"" << sweep.rows[r] << "\" " << r;
  // Dark cells (10% and more) get white text.
  script << ")\nplot DATA using 1:2:3 with image notitle, DATA using 1:2:($3 < -1 ? stringcolumn(4) : '') with labels "
            "font ',9' notitle, DATA using 1:2:($3 >= -1 ? stringcolumn(4) : '') with labels font ',9' tc rgb 'white' "
            "notitle\n";
  const int width = int(layout.width), height = int(layout.height);
  runGnuplot(script.str(), data.str(), directory / (sweep.name + ".svg"), width, height);
  runGnuplot(script.str(), data.str(), directory / (sweep.name + ".png"), width, height);
}

// Per method: where each kind of failure first appears along the sweep, and
// the worst cell; or that none appeared.
std::string reading(const Sweep& sweep) {
  std::ostringstream text;
  for (const std::string& row : sweep.rows) {
    struct Kind {
      const char* name;
      std::function<std::size_t(const Cell&)> count;
    };
    const std::vector<Kind> kinds{
        {"non-finite pixels", [](const Cell& c) { return c.error.nonFinite; }},
        {"holes", [](const Cell& c) { return c.error.holes; }},
        {"extra pixels", [](const Cell& c) { return c.error.extra; }},
        {"Newton misses", [](const Cell& c) { return c.newtonMisses.value_or(0); }},
        {"pixels over tolerance", [](const Cell& c) { return c.overTolerance; }},
    };
    std::vector<std::string> firsts;
    for (const Kind& kind : kinds)
      for (std::size_t column = 0; column < sweep.values.size(); ++column) {
        const Cell* c = find(sweep, row, column);
        if (c && kind.count(*c)) {
          firsts.push_back(std::string(kind.name) + " from " + sweep.valueLabels[column] + " (" +
                           std::to_string(kind.count(*c)) + ")");
          break;
        }
      }
    const Cell* worst = nullptr;
    double metricMin = INFINITY, metricMax = -INFINITY;
    for (std::size_t column = 0; column < sweep.values.size(); ++column)
      if (const Cell* c = find(sweep, row, column)) {
        if (!worst || c->failureShare > worst->failureShare) worst = c;
        const double m = metricValue(*c, sweep.metrics.front());
        if (std::isfinite(m)) metricMin = std::min(metricMin, m), metricMax = std::max(metricMax, m);
      }
    if (!worst) continue;
    text << "- **" << row << "**: ";
    if (firsts.empty()) {
      text << "no failure at any value";
    } else {
      for (std::size_t i = 0; i < firsts.size(); ++i) text << (i ? "; " : "") << firsts[i];
      text << "; worst " << percent(worst->failureShare) << " of the pixels at " << sweep.valueLabels[worst->column];
    }
    if (metricMax >= metricMin)
      text << "; " << sweep.metrics.front() << " " << shortNumber(metricMin) << " to " << shortNumber(metricMax);
    text << ".\n";
  }
  return text.str();
}

}  // namespace

Cell measure(const Image& candidate, const Image& reference, const Image* coverage, const Tolerance& tolerance) {
  Cell cell;
  cell.error = compareToReference(candidate, reference);
  const double floor = beautyFloor(reference);
  std::size_t failing = 0, misses = 0, coveredHere = 0;
  double beautySum = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const std::size_t i = reference.index(x, y);
      const bool here = covered(candidate, x, y), there = covered(reference, x, y);
      if (there) ++cell.referencePixels;
      if (!finitePixel(candidate, x, y)) {
        ++failing;
        continue;
      }
      if (here) {
        const glm::vec4& b = candidate.beauty[i];
        cell.beautyMax = std::max({cell.beautyMax, double(b.r), double(b.g), double(b.b)});
        beautySum += (double(b.r) + double(b.g) + double(b.b)) / 3;
        ++coveredHere;
      }
      const bool newtonMiss = coverage && !here && neighbourhoodIs(*coverage, x, y, true);
      if (newtonMiss) ++misses;
      bool fails = newtonMiss || hole(candidate, reference, x, y) || extra(candidate, reference, x, y);
      // As in `facet parity`: silhouette pixels are judged by coverage alone.
      if (interior(candidate, reference, x, y)) {
        const double depth = depthRelativeError(candidate.depth[i], reference.depth[i]);
        const double angle = normalAngle(candidate.shadingNormal[i], reference.shadingNormal[i]);
        const double beauty = beautyRelativeError(candidate.beauty[i], reference.beauty[i], floor);
        // Written as !(within) so that a NaN error fails.
        const bool over = !(depth <= tolerance.depthRelative) || !(angle <= tolerance.normalRadians) ||
                          !(beauty <= tolerance.beautyRelative);
        if (over) ++cell.overTolerance;
        fails = fails || over;
      }
      if (fails) ++failing;
    }
  if (coverage) cell.newtonMisses = misses;
  cell.beautyMean = coveredHere ? beautySum / double(coveredHere) : 0;
  cell.failureShare = std::min(1.0, double(failing) / double(std::max<std::size_t>(cell.referencePixels, 1)));
  return cell;
}

void writeSweep(const std::filesystem::path& directory, const Sweep& sweep, Report& report) {
  writeHeatMap(directory, sweep);
  report.heading("Stability: " + sweep.title);
  report.paragraph(sweep.setup);
  report.image(sweep.name + ".svg", sweep.title + ": share of failing pixels per method and condition");
  std::vector<std::string> header{"method"};
  header.insert(header.end(), sweep.valueLabels.begin(), sweep.valueLabels.end());
  std::vector<std::vector<std::string>> failures;
  for (const std::string& row : sweep.rows) {
    failures.push_back({row});
    for (std::size_t column = 0; column < sweep.values.size(); ++column) {
      const Cell* c = find(sweep, row, column);
      failures.back().push_back(c ? tableCell(*c) : "-");
    }
  }
  report.paragraph("Failing pixels (share of the reference's covered pixels, then counts) at each " + sweep.condition +
                   ":");
  report.table(header, failures);
  for (const std::string& metric : sweep.metrics) {
    std::vector<std::vector<std::string>> values;
    for (const std::string& row : sweep.rows) {
      values.push_back({row});
      for (std::size_t column = 0; column < sweep.values.size(); ++column) {
        const Cell* c = find(sweep, row, column);
        values.back().push_back(c ? shortNumber(metricValue(*c, metric)) : "-");
      }
    }
    report.paragraph("`" + metric + "` at each " + sweep.condition + ":");
    report.table(header, values);
  }
  report.paragraph("Reading (generated from the cells above):\n\n" + reading(sweep));
}

void writeStabilityCsv(const std::filesystem::path& path, const std::vector<Sweep>& sweeps) {
  const std::vector<std::string> header{
      "sweep",         "value",         "method",        "milliseconds",   "reference_pixels", "compared",
      "nonfinite",     "holes",         "extra",         "newton_misses",  "over_tolerance",   "over_tolerance_share",
      "failure_share", "relative_rmse", "depth_rel_max", "depth_rel_mean", "normal_rad_max",   "normal_rad_mean",
      "beauty_max",    "beauty_mean",   "method_error"};
  std::vector<std::vector<std::string>> rows;
  for (const Sweep& sweep : sweeps)
    for (const Cell& c : sweep.cells) {
      const ImageError& e = c.error;
      rows.push_back({sweep.name,
                      cell(sweep.values[c.column]),
                      c.row,
                      cell(c.milliseconds),
                      std::to_string(c.referencePixels),
                      std::to_string(e.compared),
                      std::to_string(e.nonFinite),
                      std::to_string(e.holes),
                      std::to_string(e.extra),
                      c.newtonMisses ? std::to_string(*c.newtonMisses) : "",
                      std::to_string(c.overTolerance),
                      cell(e.compared ? double(c.overTolerance) / double(e.compared) : 0),
                      cell(c.failureShare),
                      cell(e.relativeRmse),
                      cell(e.depthRelativeMax),
                      cell(e.depthRelativeMean),
                      cell(e.normalRadiansMax),
                      cell(e.normalRadiansMean),
                      cell(c.beautyMax),
                      cell(c.beautyMean),
                      c.methodError ? cell(*c.methodError) : ""});
    }
  writeCsv(path, header, rows);
}

}  // namespace facet::analysis::bench::stability

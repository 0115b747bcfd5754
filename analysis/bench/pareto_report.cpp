#include "analysis/bench/pareto_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/gnuplot.h"
#include "analysis/pareto.h"
#include "engine/image/image_io.h"

namespace facet::analysis::bench::pareto {
namespace {

namespace fs = std::filesystem;

std::vector<const Point*> paretoFrontier(const std::vector<Point>& points, ErrorAxis axis) {
  std::vector<Cost> costs;
  for (const Point& p : points) costs.push_back({p.milliseconds, chartedError(p.error, axis)});
  std::vector<const Point*> frontier;
  for (std::size_t i : paretoFront(costs)) frontier.push_back(&points[i]);
  return frontier;
}

std::string series(const Point& p) { return p.backend + " " + p.setting.method; }

std::string optionalCell(double value) { return std::isfinite(value) ? cell(value) : ""; }

void writePointsCsv(const fs::path& path, const std::string& sceneName, const std::vector<Point>& points) {
  std::vector<std::vector<std::string>> rows;
  for (const Point& p : points) {
    const bool hasNormals = p.backend != "embree";
    rows.push_back({sceneName, p.backend, p.setting.method, p.setting.knob,
                    p.setting.knob.empty() ? "" : cell(p.setting.value), cell(p.milliseconds),
                    hasNormals ? cell(p.error.relativeRmse) : "", hasNormals ? cell(p.error.maxAbsolute) : "",
                    cell(p.error.depthRelativeMax), cell(p.error.depthRelativeMean),
                    hasNormals ? optionalCell(p.error.normalRadiansMax) : "",
                    hasNormals ? optionalCell(p.error.normalRadiansMean) : "", std::to_string(p.error.holes),
                    std::to_string(p.error.extra), std::to_string(p.error.nonFinite)});
  }
  writeCsv(path,
           {"scene", "backend", "method", "knob", "value", "ms", "relative_rmse", "max_abs", "depth_rel_max",
            "depth_rel_mean", "normal_rad_max", "normal_rad_mean", "holes", "extra", "non_finite"},
           rows);
}

// One colour and marker per backend and method; the frontier as a dashed
// black line under them; each point labelled with its knob.
void writeChart(const fs::path& directory, const Scenario& s, const std::vector<Point>& points,
                const std::vector<const Point*>& frontier, const std::string& subtitle) {
  std::vector<std::string> names;
  for (const Point& p : points)
    if (std::find(names.begin(), names.end(), series(p)) == names.end()) names.push_back(series(p));
  auto charted = [&](const Point& p) { return std::max(chartedError(p.error, s.axis), kChartFloor); };
  std::ostringstream data, script;
  for (const Point* p : frontier) data << p->milliseconds << " " << charted(*p) << "\n";
  data << "\n\n";
  for (const std::string& name : names) {
    for (const Point& p : points)
      if (series(p) == name)
        data << p.milliseconds << " " << charted(p) << " \""
             << (p.setting.knob.empty()
                     ? ""
                     : (p.setting.knob == "epsilon" ? "ε" : p.setting.knob) + "=" + cell(p.setting.value))
             << "\"\n";
    data << "\n\n";
  }
  static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                             "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  static constexpr int kMarkers[] = {7, 5, 9, 11, 13, 15, 6, 4};
  script << "set output OUTPUT\n"
         << "set title \"" << s.name << ": time against " << axisName(s.axis) << "\\n"
         << subtitle << "\" noenhanced\n"
         << "set logscale xy\nset grid\nset format y '10^{%L}'\nset key outside right top box font ',10'\n"
         << "set xlabel 'time per image (ms; GPU: GPU timestamps of the tracing stages)'\n"
         << "set ylabel '" << axisName(s.axis) << " vs reference'\n"
         << "plot DATA index 0 using 1:2 with lines dt 2 lw 1.5 lc rgb 'black' title 'Pareto frontier'";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const char* colour = kColours[i % std::size(kColours)];
    script << ", DATA index " << i + 1 << " using 1:2 with points pt " << kMarkers[i % std::size(kMarkers)]
           << " ps 1.3 lc rgb '" << colour << "' title '" << names[i] << "', DATA index " << i + 1
           << " using 1:2:3 with labels offset char 0.6,0.6 left font ',7' tc rgb '" << colour << "' notitle";
  }
  script << "\n";
  runGnuplot(script.str(), data.str(), directory / ("pareto_" + s.name + ".svg"), 960, 600);
  runGnuplot(script.str(), data.str(), directory / ("pareto_" + s.name + ".png"), 960, 600);
}

std::string describe(const Point& p, ErrorAxis axis) {
  return p.backend + " " + p.setting.label() + " (" + threeDigits(p.milliseconds) + " ms, " +
         threeDigits(chartedError(p.error, axis)) + ")";
}

const Point* fastestBelow(const std::vector<Point>& points, ErrorAxis axis, double threshold,
                          const std::string& backend = {}) {
  const Point* best = nullptr;
  for (const Point& p : points)
    if ((backend.empty() || p.backend == backend) && chartedError(p.error, axis) <= threshold &&
        (!best || p.milliseconds < best->milliseconds))
      best = &p;
  return best;
}

// Two to four sentences read off the measured points: who holds the
// frontier's ends, who is fastest at the "good enough" error, and how the
// backends compare there.
std::string findings(const Scenario& s, const std::vector<Point>& points, const std::vector<const Point*>& frontier) {
  std::ostringstream text;
  if (frontier.size() == 1)
    text << describe(*frontier.front(), s.axis) << " is both the fastest and the most accurate point. ";
  else
    text << "The fastest point on the frontier is " << describe(*frontier.front(), s.axis) << "; the most accurate is "
         << describe(*frontier.back(), s.axis) << ". ";
  const double threshold = goodEnough(s.axis);
  if (const Point* winner = fastestBelow(points, s.axis, threshold)) {
    text << "At " << axisName(s.axis) << " ≤ " << cell(threshold) << " the fastest is " << describe(*winner, s.axis)
         << ".";
    for (const char* other : {"gpu", "cpu", "embree"}) {
      if (other == winner->backend) continue;
      if (const Point* rival = fastestBelow(points, s.axis, threshold, other))
        text << " The fastest " << other << " point there, " << describe(*rival, s.axis) << ", takes "
             << threeDigits(rival->milliseconds / winner->milliseconds) << "× as long.";
      else if (std::any_of(points.begin(), points.end(), [&](const Point& p) { return p.backend == other; }))
        text << " No " << other << " point reaches it.";
    }
  } else {
    text << "No point reaches " << axisName(s.axis) << " ≤ " << cell(threshold) << ".";
  }
  return text.str();
}

// The render shown beside the reference: the fastest facet render that is
// good enough, else the most accurate one (Embree returns depth, no image).
const Point& shownRender(const std::vector<Point>& points, ErrorAxis axis) {
  const Point *fastest = nullptr, *mostAccurate = nullptr;
  for (const Point& p : points) {
    if (p.image.pixelCount() == 0) continue;
    const double error = chartedError(p.error, axis);
    if (error <= goodEnough(axis) && (!fastest || p.milliseconds < fastest->milliseconds)) fastest = &p;
    if (!mostAccurate || error < chartedError(mostAccurate->error, axis)) mostAccurate = &p;
  }
  return fastest ? *fastest : *mostAccurate;
}
}  // namespace

std::string threeDigits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

void reportScenario(const Scenario& s, const std::vector<Point>& points, const Image& reference,
                    const fs::path& directory, const std::string& relative, const std::string& subtitle,
                    const std::string& notes, Report& report) {
  const std::vector<const Point*> frontier = paretoFrontier(points, s.axis);
  writePointsCsv(directory / ("pareto_" + s.name + ".csv"), s.name, points);
  writeChart(directory, s, points, frontier, subtitle);

  const float exposure = middleGreyExposure(reference);
  writePng(directory / ("pareto_" + s.name + "_reference.png"), reference, exposure);
  const Point& shown = shownRender(points, s.axis);
  const bool shownIsGoodEnough = chartedError(shown.error, s.axis) <= goodEnough(s.axis);

  report.heading("Pareto: " + s.name);
  report.paragraph(s.description + ". " + subtitle + ". CSV: [" + relative + "/pareto_" + s.name + ".csv](" + relative +
                   "/pareto_" + s.name + ".csv). " + notes);
  report.image(relative + "/pareto_" + s.name + ".svg", s.name + ": time against " + axisName(s.axis));
  report.image(relative + "/pareto_" + s.name + "_reference.png", "reference");
  writePng(directory / ("pareto_" + s.name + "_fastest.png"), shown.image, exposure);
  report.image(relative + "/pareto_" + s.name + "_fastest.png", shown.backend + " " + shown.setting.label());
  report.paragraph("Above: the reference, then " + shown.backend + " " + shown.setting.label() + ", " +
                   (shownIsGoodEnough ? "the fastest render with " : "the most accurate render (none reaches ") +
                   axisName(s.axis) + " ≤ " + cell(goodEnough(s.axis)) + (shownIsGoodEnough ? "" : ")") +
                   ", at the same exposure.");
  std::vector<std::vector<std::string>> rows;
  for (const Point* p : frontier)
    rows.push_back({p->backend, p->setting.label(), threeDigits(p->milliseconds),
                    threeDigits(chartedError(p->error, s.axis)), threeDigits(p->error.depthRelativeMax),
                    std::to_string(p->error.holes)});
  report.table({"backend", "method", "ms", axisName(s.axis), "depth rel. max", "holes"}, rows);
  report.paragraph(findings(s, points, frontier));
}

}  // namespace facet::analysis::bench::pareto

#include "analysis/bench/cycles_sections.h"

#include <cmath>
#include <cstdio>

#include "analysis/image_compare.h"
#include "analysis/timing.h"

namespace facet::analysis::bench {

namespace fs = std::filesystem;

std::optional<peers::CyclesPeer> findCyclesPeer(const fs::path& root, const std::string& section, Report& report) {
  const fs::path script = root / "tools/blender/cycles_scene.py";
  const std::optional<fs::path> blender = peers::findBlender();
  if (blender && fs::exists(script)) return peers::CyclesPeer{*blender, script};
  const std::string note =
      !blender ? "blender is not on PATH and FACET_BLENDER is unset" : script.string() + " is not under --root";
  std::printf("%s: skipped: %s\n", section.c_str(), note.c_str());
  report.paragraph("Skipped: " + note + ".");
  return std::nullopt;
}

std::optional<double> timeToError(const std::vector<Point>& curve, double error) {
  for (std::size_t i = 0; i < curve.size(); ++i) {
    if (curve[i].relativeRmse > error) continue;
    if (i == 0) return curve[0].milliseconds;
    const Point &a = curve[i - 1], &b = curve[i];
    const double t = std::log(error / a.relativeRmse) / std::log(b.relativeRmse / a.relativeRmse);
    return std::exp(std::log(a.milliseconds) + t * std::log(b.milliseconds / a.milliseconds));
  }
  return std::nullopt;
}

Point timedPoint(const std::string& curve, int samples, int repeats, const std::function<RenderReport()>& render,
                 const Image& reference) {
  Image image;
  const double ms = medianMilliseconds(repeats, [&] {
    RenderReport r = render();
    image = std::move(r.image);
    return traceMilliseconds(r);
  });
  const Point point{curve, samples, ms, compareToReference(image, reference).relativeRmse};
  std::printf("  facet %-22s N=%-4d %9.1f ms  relative RMSE %.4f\n", curve.c_str(), samples, ms, point.relativeRmse);
  std::fflush(stdout);
  return point;
}

std::string verdict(const std::vector<std::vector<Point>>& curves, const Point& target) {
  std::optional<double> fastest;
  std::string fastestCurve;
  for (const std::vector<Point>& curve : curves)
    if (const std::optional<double> t = timeToError(curve, target.relativeRmse); t && (!fastest || *t < *fastest))
      fastest = t, fastestCurve = curve.front().curve;
  char text[256];
  if (fastest)
    std::snprintf(text, sizeof text,
                  "facet reaches Cycles' %d-spp error (%.3g) in %.0f ms (%s, interpolated): %.2fx Cycles' %.0f ms",
                  target.samples, target.relativeRmse, *fastest, fastestCurve.c_str(), *fastest / target.milliseconds,
                  target.milliseconds);
  else
    std::snprintf(text, sizeof text, "facet does not reach Cycles' %d-spp error (%.3g) on any measured curve",
                  target.samples, target.relativeRmse);
  return text;
}

}  // namespace facet::analysis::bench

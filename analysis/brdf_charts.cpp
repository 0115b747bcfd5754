#include "analysis/brdf_charts.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "analysis/gnuplot.h"
#include "materials/albedo.h"
#include "materials/models.h"

namespace facet::analysis {
namespace {

std::string describe(const materials::Material& m) {
  std::ostringstream text;
  text << materials::modelName(materials::kDistributions, m.distribution) << " / "
       << materials::modelName(materials::kGeometryTerms, m.geometry) << " / "
       << materials::modelName(materials::kFresnelTerms, m.fresnel) << ", alpha " << m.alpha;
  return text.str();
}

}  // namespace

void writeLobeChart(const materials::Material& material, double theta_v, const std::filesystem::path& out) {
  rules::f64::BrdfParams p = materials::toParams64(material);
  const double to_radians = std::numbers::pi / 180;
  const glm::dvec3 n(0, 0, 1), v(-std::sin(theta_v * to_radians), 0, std::cos(theta_v * to_radians));
  std::ostringstream data;
  double extent = 0;
  for (int i = 0; i <= 720; ++i) {
    double theta = (-90 + 0.25 * i) * to_radians;
    glm::dvec3 l(std::sin(theta), 0, std::cos(theta));
    glm::dvec3 f = rules::f64::brdf_evaluate(p, n, l, v) * std::max(l.z, 0.0);
    double r = (f.x + f.y + f.z) / 3;
    extent = std::max(extent, r);
    data << r * l.x << " " << r * l.z << "\n";
  }
  extent = extent > 0 ? extent * 1.1 : 1;
  std::ostringstream script;
  script << "set output OUTPUT\n"
         << "set title \"f(l,v) (n.l) in the plane of incidence, theta_v = " << theta_v << " deg\\n"
         << describe(material) << "\" noenhanced\n"
         << "set size ratio -1\nset grid\nset key top right\n"
         << "set xrange [" << -extent << ":" << extent << "]\nset yrange [0:" << extent << "]\n"
         << "set arrow from " << v.x * extent << "," << v.z * extent << ",0 to 0,0 lc rgb 'gray40' lw 2\n"
         << "plot DATA using 1:2 with lines lw 2 lc rgb '#c0392b' title 'f (n.l), mean of RGB'\n";
  runGnuplot(script.str(), data.str(), out);
}

void writeAlbedoChart(const materials::Material& material, const std::vector<double>& alphas,
                      const std::filesystem::path& out) {
  std::ostringstream data, script;
  for (double alpha : alphas) {
    rules::f64::BrdfParams p = materials::toParams64(material);
    p.alpha = alpha;
    for (int i = 0; i <= 45; ++i) {
      double theta = std::min(2.0 * i, 89.9);
      materials::AlbedoResult r = materials::directionalAlbedo(p, std::cos(theta * std::numbers::pi / 180), 64);
      data << theta << " " << (r.albedo.x + r.albedo.y + r.albedo.z) / 3 << "\n";
    }
    data << "\n\n";  // gnuplot data block separator
  }
  script << "set output OUTPUT\n"
         << "set title \"directional albedo E(theta_v)\\n"
         << describe(material) << "\" noenhanced\n"
         << "set xlabel 'theta_v (degrees)' noenhanced\nset ylabel 'E'\nset grid\n"
         << "set xrange [0:90]\nset yrange [0:*]\nset key bottom left\nplot ";
  for (size_t k = 0; k < alphas.size(); ++k)
    script << (k ? ", " : "") << "DATA index " << k << " using 1:2 with lines lw 2 title 'alpha " << alphas[k] << "'";
  script << "\n";
  runGnuplot(script.str(), data.str(), out);
}

}  // namespace facet::analysis

// facet plot lobe | albedo: plots in the spirit of Disney's BRDF Explorer,
// drawn by gnuplot (run as a separate process) into SVG or PNG.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "commands.h"
#include "gnuplot.h"
#include "material_options.h"
#include "materials/albedo.h"
#include "materials/models.h"

namespace facet::cli {
namespace {

struct PlotOptions {
  MaterialOptions material;
  std::string out;
  std::string theta_v = "45";
  std::string alphas;
};

std::string describe(const materials::Material& m) {
  std::ostringstream text;
  text << materials::modelName(materials::kDistributions, m.distribution) << " / "
       << materials::modelName(materials::kGeometryTerms, m.geometry) << " / "
       << materials::modelName(materials::kFresnelTerms, m.fresnel) << ", alpha " << m.alpha;
  return text.str();
}

// Polar lobe in the plane of incidence: r(theta_l) = f(l, v)(n.l), v fixed
// on the left, l sweeping the upper half plane (BRDF Explorer's polar plot).
void plotLobe(const PlotOptions& o) {
  materials::Material material = resolveMaterial(o.material);
  double theta_v = parseNumber("--theta-v", o.theta_v);
  if (theta_v < 0 || theta_v >= 90) throw std::invalid_argument("--theta-v: must be in [0, 90)");
  materials::f64::BrdfParams p = materials::toParams64(material);
  const double to_radians = std::numbers::pi / 180;
  const glm::dvec3 n(0, 0, 1), v(-std::sin(theta_v * to_radians), 0, std::cos(theta_v * to_radians));
  std::ostringstream data;
  double extent = 0;
  for (int i = 0; i <= 720; ++i) {
    double theta = (-90 + 0.25 * i) * to_radians;
    glm::dvec3 l(std::sin(theta), 0, std::cos(theta));
    glm::dvec3 f = materials::f64::brdf_evaluate(p, n, l, v) * std::max(l.z, 0.0);
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
  runGnuplot(script.str(), data.str(), o.out);
}

// E(theta_v) from 0 to 90 degrees, for the material's alpha or for each
// value of --alphas.
void plotAlbedo(const PlotOptions& o) {
  materials::Material material = resolveMaterial(o.material);
  std::vector<double> alphas;
  if (o.alphas.empty()) {
    alphas.push_back(material.alpha);
  } else {
    std::stringstream list(o.alphas);
    for (std::string item; std::getline(list, item, ',');) {
      double alpha = parseNumber("--alphas", item);
      if (alpha < 0 || alpha > 1) throw std::invalid_argument("--alphas: each must be in [0, 1]");
      alphas.push_back(alpha);
    }
  }
  std::ostringstream data, script;
  for (double alpha : alphas) {
    materials::f64::BrdfParams p = materials::toParams64(material);
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
  runGnuplot(script.str(), data.str(), o.out);
}

}  // namespace

void addPlotCommand(CLI::App& app) {
  auto* plot = app.add_subcommand("plot", "BRDF Explorer style plots (gnuplot, SVG or PNG)");
  plot->require_subcommand(1);

  auto lobe_options = std::make_shared<PlotOptions>();
  auto* lobe = plot->add_subcommand("lobe", "Polar plot of f(l,v)(n.l) in the plane of incidence");
  addMaterialOptions(*lobe, lobe_options->material);
  lobe->add_option("--theta-v", lobe_options->theta_v, "view angle from n, degrees (default 45)");
  lobe->add_option("--out", lobe_options->out, "output image, .svg or .png")->required();
  lobe->callback([lobe_options] { plotLobe(*lobe_options); });

  auto albedo_options = std::make_shared<PlotOptions>();
  auto* albedo = plot->add_subcommand("albedo", "Directional albedo against the view angle");
  addMaterialOptions(*albedo, albedo_options->material);
  albedo->add_option("--alphas", albedo_options->alphas, "curves for these alphas: a,b,c");
  albedo->add_option("--out", albedo_options->out, "output image, .svg or .png")->required();
  albedo->callback([albedo_options] { plotAlbedo(*albedo_options); });
}

}  // namespace facet::cli

// facet plot lobe | albedo: BRDF Explorer style charts (analysis/brdf_charts.h).
#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "analysis/brdf_charts.h"
#include "commands.h"
#include "material_options.h"

namespace facet::cli {
namespace {

struct PlotOptions {
  MaterialOptions material;
  std::string out;
  std::string theta_v = "45";
  std::string alphas;
};

void plotLobe(const PlotOptions& o) {
  const materials::Material material = resolveMaterial(o.material);
  const double theta_v = parseNumber("--theta-v", o.theta_v);
  if (theta_v < 0 || theta_v >= 90) throw std::invalid_argument("--theta-v: must be in [0, 90)");
  analysis::writeLobeChart(material, theta_v, o.out);
}

// The material's alpha, or each value of --alphas.
void plotAlbedo(const PlotOptions& o) {
  const materials::Material material = resolveMaterial(o.material);
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
  analysis::writeAlbedoChart(material, alphas, o.out);
}

}  // namespace

void addPlotCommand(CLI::App& app) {
  auto* plot = app.add_subcommand("plot", "BRDF Explorer style plots (gnuplot, SVG or PNG)");
  plot->require_subcommand(1);
  const auto add = [plot](const char* name, const char* description, void (*draw)(const PlotOptions&)) {
    auto options = std::make_shared<PlotOptions>();
    CLI::App* command = addMaterialCommand(*plot, name, description, options->material);
    command->add_option("--out", options->out, "output image, .svg or .png")->required();
    command->callback([options, draw] { draw(*options); });
    return std::pair{command, options};
  };
  const auto [lobe, lobeOptions] = add("lobe", "Polar plot of f(l,v)(n.l) in the plane of incidence", plotLobe);
  lobe->add_option("--theta-v", lobeOptions->theta_v, "view angle from n, degrees (default 45)");
  const auto [albedo, albedoOptions] = add("albedo", "Directional albedo against the view angle", plotAlbedo);
  albedo->add_option("--alphas", albedoOptions->alphas, "curves for these alphas: a,b,c");
}

}  // namespace facet::cli

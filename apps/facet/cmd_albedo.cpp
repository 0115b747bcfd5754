// facet albedo: directional albedo E(mu) by deterministic quadrature.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "commands.h"
#include "engine/ibl/compensation_tables.h"
#include "engine/ibl/prefiltered_environment.h"
#include "material_options.h"
#include "materials/albedo.h"

namespace facet::cli {
namespace {

struct AlbedoOptions {
  MaterialOptions material;
  std::string mu;
  int nodes = 256;
  bool json = false;
};

void runAlbedo(const AlbedoOptions& o) {
  materials::Material material = resolveMaterial(o.material);
  double mu = parseNumber("--mu", o.mu);
  if (mu < 0 || mu > 1) throw std::invalid_argument("--mu: must be in [0, 1] (cos theta_v)");
  if (o.nodes < 2 || o.nodes % 2 != 0 || o.nodes > 4096)
    throw std::invalid_argument("--nodes: must be even, in [2, 4096]");
  const rules::f64::BrdfParams params = materials::toParams64(material);
  materials::AlbedoResult r = materials::directionalAlbedo(params, mu, o.nodes);
  // With multiple-scattering compensation the specular lobe is scaled by a
  // factor of n.v alone, read from the renderer's albedo table.
  const glm::dvec3 factor = ibl::energyCompensationOnDemand(params, mu, ibl::compensationTableSettings());
  const glm::dvec3 compensatedSpecular = r.specular * factor;
  const glm::dvec3 compensated = compensatedSpecular + r.diffuse + r.coat + r.sheen;
  // Without Fresnel or colored parameters all channels agree; otherwise the
  // scalar is their mean and the channels are in albedo_rgb.
  double albedo = (r.albedo.x + r.albedo.y + r.albedo.z) / 3;
  auto rgb = [](glm::dvec3 c) { return nlohmann::json::array({c.x, c.y, c.z}); };
  if (o.json) {
    nlohmann::json out = {{"material", materials::toJson(material)},
                          {"mu", mu},
                          {"albedo", albedo},
                          {"albedo_rgb", rgb(r.albedo)},
                          {"specular_rgb", rgb(r.specular)},
                          {"diffuse_rgb", rgb(r.diffuse)},
                          {"coat_rgb", rgb(r.coat)},
                          {"sheen_rgb", rgb(r.sheen)},
                          {"error_estimate", r.error_estimate},
                          {"nodes", r.nodes},
                          {"energy_compensated",
                           {{"albedo", (compensated.x + compensated.y + compensated.z) / 3},
                            {"albedo_rgb", rgb(compensated)},
                            {"specular_rgb", rgb(compensatedSpecular)},
                            {"factor_rgb", rgb(factor)}}}};
    std::printf("%s\n", out.dump(2).c_str());
    return;
  }
  std::printf("E(mu = %g) = %.9f   rgb %.9f %.9f %.9f   (specular %.9f %.9f %.9f, diffuse %.9f %.9f %.9f)\n", mu,
              albedo, r.albedo.x, r.albedo.y, r.albedo.z, r.specular.x, r.specular.y, r.specular.z, r.diffuse.x,
              r.diffuse.y, r.diffuse.z);
  std::printf("with energy compensation: E = %.9f   rgb %.9f %.9f %.9f   (specular x %.6f %.6f %.6f)\n",
              (compensated.x + compensated.y + compensated.z) / 3, compensated.x, compensated.y, compensated.z,
              factor.x, factor.y, factor.z);
  std::printf("estimated error %.2g (|E with %d nodes - E with %d|, Gauss-Legendre per dimension)\n", r.error_estimate,
              r.nodes, r.nodes / 2);
}

}  // namespace

void addAlbedoCommand(CLI::App& app) {
  auto options = std::make_shared<AlbedoOptions>();
  auto* command = addMaterialCommand(
      app, "albedo", "Directional albedo E(mu) = integral of f(l, v)(n.l) dl, F = 1 unless given", options->material);
  command->add_option("--mu", options->mu, "cos theta_v in [0, 1]")->required();
  command->add_option("--nodes", options->nodes, "quadrature nodes per dimension (default 256)");
  command->add_flag("--json", options->json, "machine-readable output");
  command->callback([options] { runAlbedo(*options); });
}

}  // namespace facet::cli

// facet brdf: one evaluation of f(l, v) with all its factors and the pdfs of
// the three sampling techniques.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "commands.h"
#include "material_options.h"
#include "materials/models.h"

namespace facet::cli {
namespace {

struct BrdfOptions {
  MaterialOptions material;
  std::string theta_l = "45", theta_v = "45", phi = "180";
  bool json = false;
};

// In the local frame n = z: l in the xz plane, v at azimuth phi from it
// (phi = 180 puts v in l's mirror plane).
glm::dvec3 direction(double theta_degrees, double phi_degrees) {
  double t = theta_degrees * std::numbers::pi / 180, p = phi_degrees * std::numbers::pi / 180;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

void runBrdf(const BrdfOptions& o) {
  materials::Material material = resolveMaterial(o.material);
  double theta_l = parseNumber("--theta-l", o.theta_l);
  double theta_v = parseNumber("--theta-v", o.theta_v);
  double phi = parseNumber("--phi", o.phi);
  const glm::dvec3 n(0, 0, 1), l = direction(theta_l, 0), v = direction(theta_v, phi);
  rules::f64::BrdfParams p = materials::toParams64(material);
  rules::f64::BrdfTerms t = rules::f64::brdf_terms(p, n, l, v);
  // f is the whole material's: the base's terms below, under a sheen and a
  // clear coat where the material has them (rules/shading/sheen.h,
  // clearcoat.h).
  const glm::dvec3 f = rules::f64::brdf_evaluate(p, n, l, v);
  nlohmann::json pdf;
  for (const materials::ModelName& technique : materials::kSamplingTechniques)
    pdf[std::string(technique.name)] = rules::f64::direction_pdf(technique.id, p, n, l, v);
  auto rgb = [](glm::dvec3 c) { return nlohmann::json::array({c.x, c.y, c.z}); };
  nlohmann::json out = {
      {"material", materials::toJson(material)},
      {"theta_l", theta_l},
      {"theta_v", theta_v},
      {"phi", phi},
      {"f", rgb(f)},
      {"specular", rgb(t.specular)},
      {"diffuse", rgb(t.diffuse)},
      {"D", t.D},
      {"G", t.G},
      {"F", rgb(t.F)},
      {"pdf", pdf},
  };
  if (p.clearcoat > 0) out["coat"] = rgb(rules::f64::coat_evaluate(p, l, v));
  if (rules::f64::has_sheen(p))
    out["sheen"] = rgb(rules::f64::sheen_layer(p, rules::f64::sheen_lobe(p.sheen_alpha, n, l, v),
                                               rules::f64::sheen_albedo(p, v.z), rules::f64::sheen_albedo(p, l.z))
                           .sheen);
  if (o.json) {
    std::printf("%s\n", out.dump(2).c_str());
    return;
  }
  std::printf("material  %s\n", out["material"].dump().c_str());
  std::printf("angles    theta_l %g, theta_v %g, phi %g degrees\n", theta_l, theta_v, phi);
  std::printf("f         %.9g %.9g %.9g   (specular %.9g %.9g %.9g + diffuse %.9g %.9g %.9g)\n", f.x, f.y, f.z,
              t.specular.x, t.specular.y, t.specular.z, t.diffuse.x, t.diffuse.y, t.diffuse.z);
  std::printf("D         %.9g\nG         %.9g\nF         %.9g %.9g %.9g\n", t.D, t.G, t.F.x, t.F.y, t.F.z);
  for (const materials::ModelName& technique : materials::kSamplingTechniques)
    std::printf("pdf %-12s %.9g  (%s)\n", technique.name.data(), pdf[std::string(technique.name)].get<double>(),
                technique.description.data());
}

}  // namespace

void addBrdfCommand(CLI::App& app) {
  auto options = std::make_shared<BrdfOptions>();
  auto* command =
      addMaterialCommand(app, "brdf", "Evaluate f(l, v) = F G D / (4 (n.l)(n.v)) + c_diff/pi with its factors and pdfs",
                         options->material);
  command->add_option("--theta-l", options->theta_l, "angle of l from n, degrees (default 45)");
  command->add_option("--theta-v", options->theta_v, "angle of v from n, degrees (default 45)");
  command->add_option("--phi", options->phi, "azimuth of v relative to l, degrees (default 180: mirror plane)");
  command->add_flag("--json", options->json, "machine-readable output");
  command->callback([options] { runBrdf(*options); });
}

}  // namespace facet::cli

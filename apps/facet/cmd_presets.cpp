// facet presets: the course's F(0) tables.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

#include "commands.h"
#include "engine/image/color.h"
#include "materials/presets.h"

namespace facet::cli {

void addPresetsCommand(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  auto* command = app.add_subcommand("presets", "List the material presets (F(0) tables of the SIGGRAPH 2010 course)");
  command->add_flag("--json", *json, "machine-readable output");
  command->callback([json] {
    auto rgb = [](glm::dvec3 c) { return nlohmann::json::array({c.x, c.y, c.z}); };
    nlohmann::json list = nlohmann::json::array();
    for (const materials::Preset& p : materials::presets()) {
      nlohmann::json entry = {{"name", p.name},
                              {"label", p.label},
                              {"metal", p.metal},
                              {"f0_linear", rgb(p.f0_linear)},
                              {"f0_srgb_printed", rgb(p.f0_srgb)},
                              {"f0_srgb", rgb(linearToSrgb(p.f0_linear))}};
      if (!p.metal) entry["ior"] = materials::iorFromF0(p.f0_linear.x);
      if (p.transmission > 0) entry["transmission"] = p.transmission;
      if (std::isfinite(p.attenuationDistance)) {
        entry["attenuation_color"] = rgb(p.attenuationColor);
        entry["attenuation_distance"] = p.attenuationDistance;
      }
      list.push_back(entry);
    }
    if (*json) {
      std::printf("%s\n", list.dump(2).c_str());
      return;
    }
    std::printf("%-18s %-22s %-6s %-16s %-16s %-16s %s\n", "name", "label", "kind", "F0 linear", "F0 sRGB printed",
                "F0 sRGB (ours)", "ior");
    for (const materials::Preset& p : materials::presets()) {
      glm::dvec3 srgb = linearToSrgb(p.f0_linear);
      std::printf("%-18s %-22s %-6s %.2f,%.2f,%.2f   %.2f,%.2f,%.2f   %.3f,%.3f,%.3f", p.name.data(), p.label.data(),
                  p.metal ? "metal" : "insul", p.f0_linear.x, p.f0_linear.y, p.f0_linear.z, p.f0_srgb.x, p.f0_srgb.y,
                  p.f0_srgb.z, srgb.x, srgb.y, srgb.z);
      if (!p.metal) std::printf("  %.3f", materials::iorFromF0(p.f0_linear.x));
      if (p.transmission > 0) std::printf("  transparent%s", std::isfinite(p.attenuationDistance) ? ", absorbing" : "");
      std::printf("\n");
    }
  });
}

}  // namespace facet::cli

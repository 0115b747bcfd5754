// facet brdf-precision: the float-vs-double sweep of docs/shading.md.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>

#include "commands.h"
#include "materials/precision.h"

namespace facet::cli {

void addBrdfPrecisionCommand(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  auto* command = app.add_subcommand(
      "brdf-precision", "Float vs double over a dense sweep of every D x G x F (the table in docs/shading.md)");
  command->add_flag("--json", *json, "machine-readable output");
  command->callback([json] {
    materials::PrecisionReport report = materials::precisionSweep();
    if (*json)
      std::printf("%s\n", materials::toJson(report).dump(2).c_str());
    else
      std::printf("%s", materials::toMarkdown(report).c_str());
  });
}

}  // namespace facet::cli

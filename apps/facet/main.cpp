// facet: a thin command-line layer over the library. Every command's work is
// reachable from C++; this file only wires sub-commands and reports errors.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"facet: physically based materials on subdivision surfaces, GPU and CPU"};
  app.require_subcommand(1);
  facet::cli::addInfoCommand(app);
  facet::cli::addRenderCommand(app);
  facet::cli::addBrdfCommand(app);
  facet::cli::addAlbedoCommand(app);
  facet::cli::addPresetsCommand(app);
  facet::cli::addPlotCommand(app);
  facet::cli::addBrdfPrecisionCommand(app);
  facet::cli::addParityCommand(app);
  facet::cli::addIblChartCommand(app);
  facet::cli::addBenchCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facet: error: %s\n", e.what());
    return 1;
  }
  return 0;
}

// Each facet sub-command lives in its own cmd_*.cpp and registers itself here.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace facet::scene {
struct Scene;
}

namespace facet::cli {

void addInfoCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addBrdfCommand(CLI::App& app);
void addAlbedoCommand(CLI::App& app);
void addPresetsCommand(CLI::App& app);
void addPlotCommand(CLI::App& app);
void addBrdfPrecisionCommand(CLI::App& app);
void addParityCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addIblChartCommand(CLI::App& app);

// Shared by render and parity: --size WIDTHxHEIGHT and --method exact|tess.
void applyImageSize(const std::string& size, scene::Scene& scene);
void applyMethod(const std::string& method, scene::Scene& scene);

}  // namespace facet::cli

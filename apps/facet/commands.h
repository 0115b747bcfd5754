// Each facet sub-command lives in its own cmd_*.cpp and registers itself here.
#pragma once

namespace CLI {
class App;
}

namespace facet::cli {

void addInfoCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addPreviewCommand(CLI::App& app);
void addMergeCommand(CLI::App& app);
void addBrdfCommand(CLI::App& app);
void addAlbedoCommand(CLI::App& app);
void addPresetsCommand(CLI::App& app);
void addPlotCommand(CLI::App& app);
void addBrdfPrecisionCommand(CLI::App& app);
void addParityCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addIblChartCommand(CLI::App& app);

}  // namespace facet::cli

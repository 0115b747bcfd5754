// Each facet sub-command lives in its own cmd_*.cpp and registers itself here.
#pragma once

namespace CLI {
class App;
}

namespace facet::cli {

void addInfoCommand(CLI::App& app);

}  // namespace facet::cli

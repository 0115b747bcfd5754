// facet: a thin command-line layer over the library. Every command's work is
// reachable from C++; this file only wires sub-commands and reports errors,
// each as one line "facet: error: ..." and an exit code from exit_codes.h.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "commands.h"
#include "engine/gpu/gpu.h"
#include "engine/image/image_io.h"
#include "exit_codes.h"
#include "scenes/input_error.h"

namespace {

// CLI11 reads "nan" and "inf" as numbers, and its ranges let NaN through;
// every floating-point option of every command takes finite numbers only.
void requireFiniteNumbers(CLI::App& command) {
  const CLI::Validator finite(
      [](std::string& text) {
        double value = 0;
        return CLI::detail::lexical_cast(text, value) && !std::isfinite(value)
                   ? "expected a finite number, got '" + text + "'"
                   : std::string();
      },
      "FINITE");
  for (CLI::Option* option : command.get_options())
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finite);
  for (CLI::App* subcommand : command.get_subcommands({})) requireFiniteNumbers(*subcommand);
}

int fail(facet::cli::ExitCode code, const std::string& message) {
  std::fprintf(stderr, "facet: error: %s\n", message.c_str());
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace facet::cli;
  CLI::App app{"facet: physically based materials on subdivision surfaces, GPU and CPU"};
  app.require_subcommand(1);
  addInfoCommand(app);
  addRenderCommand(app);
  addMergeCommand(app);
  addBrdfCommand(app);
  addAlbedoCommand(app);
  addPresetsCommand(app);
  addPlotCommand(app);
  addBrdfPrecisionCommand(app);
  addParityCommand(app);
  addIblChartCommand(app);
  addBenchCommand(app);
  requireFiniteNumbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == int(CLI::ExitCodes::Success)) return app.exit(e);  // --help
    return fail(kBadInput, e.what());
  } catch (const facet::scene::InputError& e) {
    return fail(kBadInput, e.what());
  } catch (const std::invalid_argument& e) {
    return fail(kBadInput, e.what());
  } catch (const facet::OutputError& e) {
    return fail(kOutputFailed, e.what());
  } catch (const facet::gpu::Error& e) {
    return fail(kGpuFailed, e.what());
  } catch (const CheckFailed& e) {
    return fail(kCheckFailed, e.what());
  } catch (const std::bad_alloc&) {
    return fail(kInternal, "out of memory");
  } catch (const std::exception& e) {
    return fail(kInternal, e.what());
  }
  return kSuccess;
}

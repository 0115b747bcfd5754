// facet: a thin command-line layer over the library. Every command's work is
// reachable from C++; this file only wires sub-commands and reports errors,
// each as one line "facet: error: ..." and an exit code from exit_codes.h.
#include <CLI/CLI.hpp>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "analysis/reference_cache.h"
#include "analysis/stored_parity.h"
#include "commands.h"
#include "engine/gpu/gpu.h"
#include "engine/image/image_io.h"
#include "engine/image/child_process.h"
#include "exit_codes.h"
#include "facet/version.h"
#include "scenes/input_error.h"

namespace {

// CLI11's ranges call a word that is not a number "not in range", and they
// let NaN and Inf through: every numeric option of every command first
// takes a number, finite where it is floating-point.
void requireNumbers(CLI::App& command) {
  const CLI::Validator number(
      [](std::string& text) {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "expected a number, got '" + text + "'";
        return std::isfinite(value) ? std::string() : "expected a finite number, got '" + text + "'";
      },
      "", "number");  // no description: the help keeps CLI11's type and range
  for (CLI::Option* option : command.get_options()) {
    const std::string type = option->get_type_name();
    if (type.find("FLOAT") != std::string::npos || type.find("INT") != std::string::npos) option->transform(number);
  }
  for (CLI::App* subcommand : command.get_subcommands({})) requireNumbers(*subcommand);
}

int fail(facet::cli::ExitCode code, const std::string& message) {
  std::fprintf(stderr, "facet: error: %s\n", message.c_str());
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace facet::cli;
  facet::analysis::recordProgramAtStart();  // before any Vulkan driver is loaded
  CLI::App app{"facet: physically based materials on subdivision surfaces, GPU and CPU"};
  app.set_version_flag("--version", "facet " FACET_VERSION_STRING);
  app.require_subcommand(1);
  addInfoCommand(app);
  addRenderCommand(app);
  addPreviewCommand(app);
  addMergeCommand(app);
  addBrdfCommand(app);
  addAlbedoCommand(app);
  addPresetsCommand(app);
  addPlotCommand(app);
  addBrdfPrecisionCommand(app);
  addParityCommand(app);
  addCompareCommand(app);
  addIblChartCommand(app);
  addBenchCommand(app);
  requireNumbers(app);
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
  } catch (const facet::analysis::NotComparable& e) {
    return fail(kNotComparable, e.what());
  } catch (const facet::Interrupted& e) {
    // The program it ran has ended and the command has cleaned up as it
    // unwound: it now ends as the signal would have ended it.
    fail(kInternal, e.what());
    std::signal(e.signal(), SIG_DFL);
    std::raise(e.signal());
    return kInternal;
  } catch (const std::bad_alloc&) {
    return fail(kInternal, "out of memory");
  } catch (const std::exception& e) {
    return fail(kInternal, e.what());
  }
  return kSuccess;
}

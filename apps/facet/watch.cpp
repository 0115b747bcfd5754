#include "watch.h"

#include <signal.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/image/signal_handlers.h"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

volatile std::sig_atomic_t stopRequested = 0;
extern "C" void requestStop(int) { stopRequested = 1; }

// SIGINT and SIGTERM end the watch between passes, after the outputs of the
// last are in place; the previous handlers come back when it ends.
class StopOnSignals {
 public:
  StopOnSignals() {
    stopRequested = 0;  // before the handlers, so that a signal from then on counts
    handlers_.emplace(std::initializer_list<int>{SIGINT, SIGTERM}, requestStop);
  }
  bool stopped() const { return stopRequested != 0; }

 private:
  std::optional<SignalHandlers> handlers_;
};

// "a.json, b.png and 3 more"
std::string nameFiles(const std::vector<fs::path>& files) {
  std::string text;
  const std::size_t shown = std::min<std::size_t>(files.size(), 3);
  for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + files[i].filename().string();
  if (files.size() > shown) text += " and " + std::to_string(files.size() - shown) + " more";
  return text;
}

void printError(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facet: error: %s\n", e.what());
    std::fflush(stderr);
  }
}

// "first picture of a.json: 64x64, 1 spp in 900 ms (load 12 ms, ...)", or
// "a.json changed: not rendered; the outputs keep the last picture"
std::string pictureLine(const WatchPicture& p) {
  const std::string what =
      p.change == 0 ? "first picture of " + nameFiles(p.files) : nameFiles(p.files) + " changed";
  if (!p.rendered) return what + ": not rendered; the outputs keep the last picture";
  const char* geometry = !p.geometryDiced ? "" : *p.geometryDiced ? ", geometry diced" : ", geometry kept";
  char numbers[200];
  std::snprintf(numbers, sizeof numbers,
                "%dx%d, %d spp in %.0f ms (load %.0f ms, render %.0f ms, its stages %.0f ms%s, write %.0f ms)",
                p.width, p.height, p.spp, p.milliseconds, p.loadMilliseconds, p.renderMilliseconds,
                p.stageMilliseconds, geometry, p.writeMilliseconds);
  return what + ": " + numbers + (p.lightTransport.empty() ? "" : "; " + p.lightTransport);
}

}  // namespace

void addWatchOptions(CLI::App& command, WatchOptions& options) {
  command.add_flag("--watch", options.watch,
                   "Render again each time the scene or a file it names changes (material files, cages, glTF files, "
                   "images, environment maps), refining each picture by passes; SIGINT or SIGTERM ends it");
  command.add_option("--watch-limit", options.limit, "With --watch: stop after this many changes (0: never)")
      ->check(CLI::Range(0, 1000000));
  command
      .add_option(
          "--watch-passes", options.passes,
          "With --watch: passes of each picture, each adding --spp samples per pixel (at least 4 after the first) and "
          "rewriting the outputs")
      ->check(CLI::Range(1, 4096));
}

void checkWatchFlags(const CLI::App& command, const WatchOptions& options, const FarmOptions& farm) {
  if (!options.watch) {
    for (const char* flag : {"--watch-limit", "--watch-passes"})
      if (command.get_option(flag)->count() > 0) throw std::invalid_argument(std::string(flag) + ": needs --watch");
    return;
  }
  const std::pair<const char*, bool> refused[] = {
      {"--frames", farm.framesGiven}, {"--frame", farm.frame.has_value()}, {"--turntable", farm.turntable.has_value()},
      {"--tile", !farm.tile.empty()}, {"--crop", !farm.crop.empty()},      {"--json", farm.json},
      {"--seeds", farm.seedsGiven}};
  for (const auto& [flag, given] : refused)
    if (given)
      throw std::invalid_argument(std::string("--watch: cannot be combined with ") + flag +
                                  ": a watch renders one whole still again and again");
}

void watchScene(Renderer& renderer, Backend backend, unsigned threads, const WatchedScene& io,
                const WatchOptions& options, bool quiet) {
  const StopOnSignals signals;
  auto say = [&](const std::string& line) {
    if (quiet) return;
    std::printf("watch: %s\n", line.c_str());
    std::fflush(stdout);
  };
  WatchEvents events;
  events.stopRequested = [&] { return signals.stopped(); };
  events.badInput = printError;
  events.picture = [&](const WatchPicture& picture) { say(pictureLine(picture)); };
  events.refined = [&](const WatchRefined& r) {
    char line[160];
    std::snprintf(line, sizeof line, "refined to %d passes, %d spp, in %.1f s", r.passes, r.samples, r.seconds);
    say(line);
  };
  SceneWatch(renderer, io, {backend, threads, options.passes, options.limit}, std::move(events)).run();
}

}  // namespace facet::cli

// facet render --watch: its flags, and engine/scene_watch.h's watch driven
// until a signal, its pictures and errors printed. README.md, "Watching a
// scene", states the behaviour.
#pragma once

#include <CLI/CLI.hpp>

#include "engine/renderer.h"
#include "engine/scene_watch.h"
#include "farm_options.h"

namespace facet::cli {

struct WatchOptions {
  bool watch = false;
  int limit = 0;    // changes to handle before it stops; 0: until SIGINT or SIGTERM
  int passes = WatchSettings{}.passes;  // of each picture, each adding the scene's spp
};

void addWatchOptions(CLI::App& command, WatchOptions& options);

// Throws std::invalid_argument where --watch meets a flag of many renders
// or of a part of one (--frames, --frame, --turntable, --tile, --crop), or
// --json, and where --watch-limit or --watch-passes come without --watch.
void checkWatchFlags(const CLI::App& command, const WatchOptions& options, const FarmOptions& farm);

// Renders the scene, then again on each change, until SIGINT or SIGTERM
// (after which it returns, the outputs complete) or options.limit changes.
// The first picture's errors propagate as `facet render`'s do; a later
// load or render that fails on bad input prints its `facet: error:` line,
// keeps the last picture and waits for the next change. `quiet`: no
// summary lines.
void watchScene(Renderer& renderer, Backend backend, unsigned threads, const WatchedScene& scene,
                const WatchOptions& options, bool quiet);

}  // namespace facet::cli

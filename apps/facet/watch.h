// facet render --watch: a picture of a scene, then a new one each time a
// file the scene depends on changes (scenes/input_file.h's InputFileLog
// names them), on one Renderer, so that the device, the compiled pipelines
// and the diced geometry, while it is the same, are kept from one picture to
// the next. Each picture is refined by passes of the scene's samples, each
// with its own random numbers (engine/adaptive_render.h's rounds), and
// written after each pass; a change ends the passes. README.md, "Watching a
// scene", states the behaviour.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

#include "engine/image/image.h"
#include "engine/renderer.h"
#include "farm_options.h"
#include "scenes/scene.h"

namespace facet::cli {

struct WatchOptions {
  bool watch = false;
  int limit = 0;    // changes to handle before it stops; 0: until SIGINT or SIGTERM
  int passes = 16;  // passes of each picture, each adding the scene's spp (watch.cpp: at least 4 after the first)
};

void addWatchOptions(CLI::App& command, WatchOptions& options);

// Throws std::invalid_argument where --watch meets a flag of many renders
// or of a part of one (--frames, --frame, --turntable, --tile, --crop), or
// --json, and where --watch-limit or --watch-passes come without --watch.
void checkWatchFlags(const CLI::App& command, const WatchOptions& options, const FarmOptions& farm);

// What a watch does with its scene: loads it as `facet render` does (bad
// input throws scene::InputError or std::invalid_argument), and writes a
// picture of it to the command's outputs: `passes` passes, whose beauty has
// `samples` samples per pixel.
struct WatchedScene {
  std::function<scene::Scene()> load;
  std::function<void(const scene::Scene& scene, const Image& image, int passes, int samples)> write;
};

// Renders the scene, then again on each change, until SIGINT or SIGTERM
// (after which it returns, the outputs complete) or options.limit changes.
// The first picture's errors propagate as `facet render`'s do; a later
// load or render that fails on bad input prints its `facet: error:` line,
// keeps the last picture and waits for the next change. `quiet`: no
// summary lines.
void watchScene(Renderer& renderer, Backend backend, unsigned threads, const WatchedScene& scene,
                const WatchOptions& options, bool quiet);

}  // namespace facet::cli

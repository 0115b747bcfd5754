// A watched scene: a picture of it, then a new one each time a file it
// depends on changes (scenes/input_file.h's InputFileLog names them), on one
// Renderer, so that the device, the compiled pipelines and the diced
// geometry, while it is the same, are kept from one picture to the next.
// Each picture is refined by passes (engine/progressive_picture.h) and
// written after each; a change ends the passes. `facet render --watch`
// drives it (README.md, "Watching a scene").
#pragma once

#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/progressive_picture.h"
#include "engine/renderer.h"
#include "scenes/scene.h"

namespace facet {

// What a watch does with its scene: loads it (bad input throws
// scene::InputError or std::invalid_argument), and writes a picture of it:
// `passes` passes, whose beauty has `samples` samples per pixel.
struct WatchedScene {
  std::function<scene::Scene()> load;
  std::function<void(const scene::Scene& scene, const Image& image, int passes, int samples)> write;
};

struct WatchSettings {
  Backend backend = Backend::Gpu;
  unsigned threads = 0;  // the CPU reference's; 0: every core
  int passes = 16;       // of each picture, each adding the scene's spp (at least 4 after the first)
  int limit = 0;         // changes run() handles before it returns; 0: until a stop
};

// A picture begun: after its first pass is written, or when its load or
// first pass failed on bad input and the outputs keep the last picture.
struct WatchPicture {
  int change = 0;  // 0: the first picture; then the changes handled so far
  // The first picture's: the files its scene read; a later one's: those that changed.
  std::vector<std::filesystem::path> files;
  bool rendered = false;
  int width = 0, height = 0, spp = 0;  // the scene's, when rendered
  double milliseconds = 0;             // from the start of the load to the first pass written
  double loadMilliseconds = 0, renderMilliseconds = 0, stageMilliseconds = 0, writeMilliseconds = 0;
  std::optional<bool> geometryDiced;  // ProgressivePicture::Pass's
  std::string lightTransport;         // what was chosen and why, where the scene left it unsaid
};

// A picture refined past its first pass, once its passes end.
struct WatchRefined {
  int passes = 0;
  int samples = 0;     // per pixel
  double seconds = 0;  // from the start of the load
};

// What the watch tells its caller; each may be empty.
struct WatchEvents {
  std::function<bool()> stopRequested;  // asked between passes, strips and polls
  // An error on bad input after the first picture's first pass: the watch
  // goes on with the last picture and waits for the next change.
  std::function<void(const std::exception_ptr& error)> badInput;
  std::function<void(const WatchPicture& picture)> picture;
  std::function<void(const WatchRefined& refined)> refined;
};

class SceneWatch {
 public:
  SceneWatch(Renderer& renderer, WatchedScene scene, const WatchSettings& settings, WatchEvents events);

  // Loads the scene and renders its picture pass by pass, writing each,
  // until its passes are done, a watched file changes or a stop. The first
  // picture's errors propagate; a later load or render that fails on bad
  // input goes to events.badInput.
  void render();

  // The watched files that differ from when the last load began: a missing
  // file is watched too, so that one a scene names renders once it appears.
  std::vector<std::filesystem::path> changedFiles() const;

  // Where a watched file changed: waits for the files to settle, so that a
  // save in several writes is read whole, and renders again. Returns whether
  // it rendered: not without a change, nor after a stop.
  bool update();

  // render(), then update() on each change, until a stop or settings.limit changes.
  void run();

 private:
  // What a file looked like.
  struct Stamp {
    bool exists = false;
    std::filesystem::file_time_type time;
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  using Stamps = std::map<std::filesystem::path, Stamp>;
  static Stamp stampOf(const std::filesystem::path& file);
  static Stamps stampsOf(const std::vector<std::filesystem::path>& files);
  static std::vector<std::filesystem::path> changedSince(const Stamps& stamps);

  void renderPasses(scene::Scene scene, WatchPicture& begun, std::chrono::steady_clock::time_point start);
  bool stopped() const { return events_.stopRequested && events_.stopRequested(); }
  void report(const WatchPicture& picture) const;
  void reportBadInput(const std::exception_ptr& error) const;

  WatchedScene scene_;
  WatchSettings settings_;
  WatchEvents events_;
  ProgressivePicture picture_;
  std::vector<std::filesystem::path> files_;  // the last good load's
  Stamps stamps_;                             // of the files watched, as the last load began
  std::vector<std::filesystem::path> changed_;  // that the update in progress handles
  int changes_ = 0;                              // handled by update()
};

}  // namespace facet

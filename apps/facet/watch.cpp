#include "watch.h"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "engine/adaptive_render.h"
#include "engine/image/sample_rounds.h"
#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "rules/rules.h"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Polling, not inotify: an editor that saves by writing a new file and
// renaming it over the old one replaces the inode a watch would be on.
constexpr auto kPollInterval = std::chrono::milliseconds(50);
// A change is read once the files have stayed as they are this long, so
// that a save in several writes is read whole.
constexpr auto kSettleInterval = std::chrono::milliseconds(20);

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

volatile std::sig_atomic_t stopRequested = 0;
extern "C" void requestStop(int) { stopRequested = 1; }

// SIGINT and SIGTERM end the watch between passes, after the outputs of the
// last are in place; the previous handlers come back when it ends.
class StopOnSignals {
 public:
  StopOnSignals() {
    stopRequested = 0;
    struct sigaction action {};
    action.sa_handler = requestStop;
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_[0]);
    sigaction(SIGTERM, &action, &previous_[1]);
  }
  ~StopOnSignals() {
    sigaction(SIGINT, &previous_[0], nullptr);
    sigaction(SIGTERM, &previous_[1], nullptr);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  bool stopped() const { return stopRequested != 0; }

 private:
  struct sigaction previous_[2];
};

// What a file looked like: a missing file is watched too, so that one a
// scene names renders once it appears.
struct Stamp {
  bool exists = false;
  fs::file_time_type time;
  std::uintmax_t size = 0;
  bool operator==(const Stamp&) const = default;
};
using Stamps = std::map<fs::path, Stamp>;

Stamp stampOf(const fs::path& file) {
  std::error_code error;
  Stamp stamp;
  stamp.time = fs::last_write_time(file, error);
  if (error) return {};
  stamp.exists = true;
  stamp.size = fs::is_regular_file(file, error) ? fs::file_size(file, error) : 0;
  return stamp;
}

Stamps stampsOf(const std::vector<fs::path>& files) {
  Stamps stamps;
  for (const fs::path& file : files) stamps[file] = stampOf(file);
  return stamps;
}

std::vector<fs::path> changedFiles(const Stamps& stamps) {
  std::vector<fs::path> changed;
  for (const auto& [file, stamp] : stamps)
    if (stampOf(file) != stamp) changed.push_back(file);
  return changed;
}

// "a.json, b.png and 3 more"
std::string nameFiles(const std::vector<fs::path>& files) {
  std::string text;
  const std::size_t shown = std::min<std::size_t>(files.size(), 3);
  for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + files[i].filename().string();
  if (files.size() > shown) text += " and " + std::to_string(files.size() - shown) + " more";
  return text;
}

// Waits for a change to the files or a stop; then for the files to settle.
std::vector<fs::path> awaitChange(const Stamps& stamps, const StopOnSignals& signals) {
  std::vector<fs::path> changed;
  while (!signals.stopped() && (changed = changedFiles(stamps)).empty()) std::this_thread::sleep_for(kPollInterval);
  for (Stamps now = stampsOf(changed); !signals.stopped();) {
    std::this_thread::sleep_for(kSettleInterval);
    if (changedFiles(now).empty()) break;
    now = stampsOf(changed);
  }
  return changed;
}

bool isBadInput(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const scene::InputError&) {
    return true;
  } catch (const std::invalid_argument&) {
    return true;
  } catch (...) {
    return false;
  }
}

void printError(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facet: error: %s\n", e.what());
    std::fflush(stderr);
  }
}

// At 1 spp a pixel's one sample passes through its centre
// (rules/camera/sample_plan.h), so passes of 1 would all be alike: the
// first pass of such a picture is a quick look, and its refining passes
// take a net of this many samples each, their mean alone the beauty.
constexpr int kRefiningSpp = 4;
// A change waits at most about this long for the refining pass in progress.
constexpr double kStripMilliseconds = 100;

// One picture, refined pass by pass until its passes are done, a file
// changes or a signal comes: the rounds of engine/adaptive_render.h over the
// whole image, the beauty their mean and the AOVs the first pass's, which
// passes through each pixel's centre.
class Picture {
 public:
  Picture(Renderer& renderer, Backend backend, unsigned threads, const WatchedScene& io)
      : renderer_(renderer), backend_(backend), threads_(threads), io_(io) {}

  // Renders pass `pass` of `scene` into the picture; returns the render's
  // wall clock, its stages' sum and, on the GPU, whether it diced its
  // geometry anew (the CPU reference keeps nothing between renders). A
  // refining pass is rendered in strips of whole rows, each of about
  // kStripMilliseconds, and ends unfinished, the picture as it was, when
  // `stale` says so between two: nothing (a change waits for a strip, not a pass).
  struct Pass {
    double renderMilliseconds = 0, stageMilliseconds = 0, writeMilliseconds = 0;
    std::string geometry;
  };
  std::optional<Pass> render(const scene::Scene& scene, int pass, const std::function<bool()>& stale) {
    const int width = scene.render.width, height = scene.render.height;
    const bool quickLook = scene.render.samplesPerPixel == 1;
    RoundFrame frame = roundFrame(scene, pass);
    if (frame.scene.environment) frame.scene.environment->seed = scene.environment->seed + std::uint32_t(pass);
    if (quickLook && pass > 0) frame.scene.render.samplesPerPixel = kRefiningSpp;
    const int roundWidth = frame.scene.render.width;
    const std::uint32_t strata = rules::f64::sample_strata(std::uint32_t(frame.scene.render.samplesPerPixel));
    const double rays = double(rules::f64::rays_per_pixel(strata)) * roundWidth;  // per row
    const int rows = pass == 0 ? height : std::clamp(int(kStripMilliseconds / (millisecondsPerRay_ * rays)), 1, height);
    Image round;  // the pass's beauty over whole rows of the round's image
    round.width = roundWidth;
    round.height = height;
    Pass timing;
    for (int y0 = 0; y0 < height; y0 += rows) {
      if (y0 > 0 && stale()) return std::nullopt;
      // Whole rows of the round's larger image: a crop narrower than the
      // image is rendered a row at a time (one submission each).
      const int y1 = std::min(height, y0 + rows);
      const PixelRect crop{0, frame.dy + y0, roundWidth, frame.dy + y1};
      const Clock::time_point start = Clock::now();
      RenderReport report = renderer_.render(frame.scene, backend_, {}, {crop, threads_});
      const double milliseconds = millisecondsSince(start);
      // By the stages: the wall clock of the first render holds the pipelines' compilation too.
      millisecondsPerRay_ = std::max(report.totalMilliseconds(), 0.01) / (rays * (y1 - y0));
      timing.renderMilliseconds += milliseconds;
      timing.stageMilliseconds += report.totalMilliseconds();
      if (backend_ == Backend::Gpu && timing.geometry != ", geometry diced")
        timing.geometry = std::any_of(report.stages.begin(), report.stages.end(),
                                      [](const StageTime& s) { return s.stage == Stage::DiceCells; })
                              ? ", geometry diced"
                              : ", geometry kept";
      round.beauty.insert(round.beauty.end(), report.image.beauty.begin(), report.image.beauty.end());
      if (pass == 0) first_ = std::move(report.image);
    }
    if (pass == 0 || (quickLook && pass == 1)) {
      rounds_.emplace(width, height, std::max(width, height));
      samples_ = 0;
    }
    rounds_->add(round, {-frame.dx, 0, width + frame.dx, height}, {0});
    samples_ += frame.scene.render.samplesPerPixel;
    passes_ = pass + 1;
    return timing;
  }

  // Writes the picture as its passes so far make it; returns its wall clock.
  double write(const scene::Scene& scene) {
    const Clock::time_point start = Clock::now();
    Image image = first_;
    image.beauty = rounds_->beauty();
    io_.write(scene, image, passes_, samples_);
    return millisecondsSince(start);
  }

  int samples() const { return samples_; }  // per pixel, in the beauty

 private:
  Renderer& renderer_;
  Backend backend_;
  unsigned threads_;
  const WatchedScene& io_;
  std::optional<SampleRounds> rounds_;
  int samples_ = 0, passes_ = 0;
  double millisecondsPerRay_ = 0;  // of the last render's stages, their fixed costs included
  Image first_;
};

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
      {"--tile", !farm.tile.empty()}, {"--crop", !farm.crop.empty()},      {"--json", farm.json}};
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
  Picture picture(renderer, backend, threads, io);
  std::vector<fs::path> files;  // the last good load's
  Stamps stamps;
  std::vector<fs::path> changed;
  std::optional<scene::Scene> scene;
  for (int changes = 0;; ++changes) {
    // The files as they were before the load began: one changed while it
    // read them is seen at the next look.
    const Stamps before = stampsOf(files);
    const Clock::time_point start = Clock::now();
    std::optional<scene::InputFileLog> log(std::in_place);
    try {
      scene = io.load();
    } catch (...) {
      if (changes == 0 || !isBadInput(std::current_exception())) throw;
      printError(std::current_exception());
      scene.reset();
    }
    const double loadMilliseconds = millisecondsSince(start);
    std::vector<fs::path> read = log->files();
    log.reset();
    if (scene) files = read;
    for (const fs::path& file : files)
      if (std::find(read.begin(), read.end(), file) == read.end()) read.push_back(file);
    stamps = stampsOf(read);
    for (const auto& [file, stamp] : before)
      if (stamps.count(file)) stamps[file] = stamp;

    const std::string what = changes == 0 ? "first picture of " + nameFiles(files) : nameFiles(changed) + " changed";
    if (!scene) say(what + ": not rendered; the outputs keep the last picture");
    int written = 0;  // passes in the outputs
    for (int pass = 0; scene && pass < options.passes && !signals.stopped(); ++pass) {
      Picture::Pass timing;
      try {
        const auto stale = [&] { return signals.stopped() || !changedFiles(stamps).empty(); };
        const std::optional<Picture::Pass> rendered = picture.render(*scene, pass, stale);
        // A refining pass of a picture whose files changed meanwhile is not worth writing.
        if (!rendered || (pass > 0 && stale())) break;
        timing = *rendered;
        timing.writeMilliseconds = picture.write(*scene);
        written = pass + 1;
      } catch (...) {
        // The first picture's errors end the command, as `facet render`'s do.
        if ((changes == 0 && pass == 0) || !isBadInput(std::current_exception())) throw;
        printError(std::current_exception());
        if (pass == 0) say(what + ": not rendered; the outputs keep the last picture");
        break;
      }
      if (pass == 0) {
        char numbers[200];
        std::snprintf(numbers, sizeof numbers,
                      "%dx%d, %d spp in %.0f ms (load %.0f ms, render %.0f ms, its stages %.0f ms%s, write %.0f ms)",
                      scene->render.width, scene->render.height, scene->render.samplesPerPixel,
                      millisecondsSince(start), loadMilliseconds, timing.renderMilliseconds, timing.stageMilliseconds,
                      timing.geometry.c_str(), timing.writeMilliseconds);
        say(what + ": " + numbers);
      }
      if (!changedFiles(stamps).empty()) break;
    }
    if (written > 1) {
      char line[160];
      std::snprintf(line, sizeof line, "refined to %d passes, %d spp, in %.1f s", written, picture.samples(),
                    millisecondsSince(start) / 1000.0);
      say(line);
    }
    if (signals.stopped() || (options.limit > 0 && changes >= options.limit)) return;
    changed = awaitChange(stamps, signals);
    if (signals.stopped()) return;
  }
}

}  // namespace facet::cli

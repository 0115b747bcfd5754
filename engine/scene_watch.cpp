#include "engine/scene_watch.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/light_transport.h"
#include "scenes/scene_geometry.h"

namespace facet {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Polling, not inotify: an editor that saves by writing a new file and
// renaming it over the old one replaces the inode a watch would be on.
constexpr auto kPollInterval = std::chrono::milliseconds(50);
// A change is read once the files have stayed as they are this long.
constexpr auto kSettleInterval = std::chrono::milliseconds(20);

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
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

}  // namespace

SceneWatch::SceneWatch(Renderer& renderer, WatchedScene scene, const WatchSettings& settings, WatchEvents events)
    : scene_(std::move(scene)),
      settings_(settings),
      events_(std::move(events)),
      picture_(renderer, settings.backend, settings.threads) {}

SceneWatch::Stamp SceneWatch::stampOf(const fs::path& file) {
  std::error_code error;
  Stamp stamp;
  stamp.time = fs::last_write_time(file, error);
  if (error) return {};
  stamp.exists = true;
  stamp.size = fs::is_regular_file(file, error) ? fs::file_size(file, error) : 0;
  return stamp;
}

SceneWatch::Stamps SceneWatch::stampsOf(const std::vector<fs::path>& files) {
  Stamps stamps;
  for (const fs::path& file : files) stamps[file] = stampOf(file);
  return stamps;
}

std::vector<fs::path> SceneWatch::changedSince(const Stamps& stamps) {
  std::vector<fs::path> changed;
  for (const auto& [file, stamp] : stamps)
    if (stampOf(file) != stamp) changed.push_back(file);
  return changed;
}

std::vector<fs::path> SceneWatch::changedFiles() const { return changedSince(stamps_); }

void SceneWatch::report(const WatchPicture& picture) const {
  if (events_.picture) events_.picture(picture);
}

void SceneWatch::reportBadInput(const std::exception_ptr& error) const {
  if (events_.badInput) events_.badInput(error);
}

void SceneWatch::render() {
  // The files as they were before the load began: one changed while it
  // read them is seen at the next look.
  const Stamps before = stampsOf(files_);
  const Clock::time_point start = Clock::now();
  std::optional<scene::Scene> scene;
  std::optional<scene::InputFileLog> log(std::in_place);
  try {
    scene = scene_.load();
  } catch (...) {
    if (changes_ == 0 || !isBadInput(std::current_exception())) throw;
    reportBadInput(std::current_exception());
  }
  WatchPicture begun;
  begun.loadMilliseconds = millisecondsSince(start);
  std::vector<fs::path> read = log->files();
  log.reset();
  // A load that failed keeps watching the last good load's files too, so
  // that undoing the edit that broke it renders again.
  if (scene) files_ = read;
  for (const fs::path& file : files_)
    if (std::find(read.begin(), read.end(), file) == read.end()) read.push_back(file);
  stamps_ = stampsOf(read);
  for (const auto& [file, stamp] : before)
    if (stamps_.count(file)) stamps_[file] = stamp;

  begun.change = changes_;
  begun.files = changes_ == 0 ? files_ : changed_;
  if (scene)
    renderPasses(std::move(*scene), begun, start);
  else
    report(begun);
}

void SceneWatch::renderPasses(scene::Scene scene, WatchPicture& begun, Clock::time_point start) {
  // Chosen once for the picture's passes and strips (scenes/light_transport.h),
  // on the geometry they then take.
  std::shared_ptr<const scene::SceneGeometry> geometry;
  if (scene::leavesLightTransportUnsaid(scene)) {
    geometry = std::make_shared<const scene::SceneGeometry>(scene::buildGeometry(scene));
    const scene::LightTransport transport = scene::chooseLightTransport(scene, *geometry);
    scene = scene::withLightTransport(std::move(scene), transport);
    begun.lightTransport = transport.note;
  }
  int written = 0;  // passes in the outputs
  for (int pass = 0; pass < settings_.passes && !stopped(); ++pass) {
    try {
      const auto stale = [&] { return stopped() || !changedFiles().empty(); };
      const std::optional<ProgressivePicture::Pass> rendered = picture_.render(scene, pass, stale, geometry);
      // A refining pass of a picture whose files changed meanwhile is not worth writing.
      if (!rendered || (pass > 0 && stale())) break;
      const Clock::time_point writing = Clock::now();
      scene_.write(scene, picture_.image(), picture_.passes(), picture_.samples());
      begun.writeMilliseconds = millisecondsSince(writing);
      begun.renderMilliseconds = rendered->renderMilliseconds;
      begun.stageMilliseconds = rendered->stageMilliseconds;
      begun.geometryDiced = rendered->geometryDiced;
      written = pass + 1;
    } catch (...) {
      // The first picture's errors end the watch, as a single render's would.
      if ((changes_ == 0 && pass == 0) || !isBadInput(std::current_exception())) throw;
      reportBadInput(std::current_exception());
      if (pass == 0) report(begun);
      break;
    }
    if (pass == 0) {
      begun.rendered = true;
      begun.width = scene.render.width;
      begun.height = scene.render.height;
      begun.spp = scene.render.samplesPerPixel;
      begun.milliseconds = millisecondsSince(start);
      report(begun);
    }
    if (!changedFiles().empty()) break;
  }
  if (written > 1 && events_.refined) events_.refined({written, picture_.samples(), millisecondsSince(start) / 1000.0});
}

bool SceneWatch::update() {
  std::vector<fs::path> changed = changedFiles();
  if (changed.empty()) return false;
  for (Stamps now = stampsOf(changed); !stopped();) {
    std::this_thread::sleep_for(kSettleInterval);
    if (changedSince(now).empty()) break;
    now = stampsOf(changed);
  }
  if (stopped()) return false;
  changed_ = std::move(changed);
  ++changes_;
  render();
  return true;
}

void SceneWatch::run() {
  render();
  while (!stopped() && !(settings_.limit > 0 && changes_ >= settings_.limit)) {
    while (!stopped() && changedFiles().empty()) std::this_thread::sleep_for(kPollInterval);
    update();
  }
}

}  // namespace facet
